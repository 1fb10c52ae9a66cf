#!/bin/sh
# Every measured figure of README.md and docs/ is what the code measures now: each
# table between `figures` markers, each number with a `fig:` key and each picture in
# docs/images/ (scripts/docs_figures.py, whose catalogue names the command behind
# each). Errors (PSNR, largest error, shares) and bytes must be the same to the digit,
# instruction counts within 0.5%, and a picture the same pixel for pixel as a fresh
# render. A failure names the file, the figure and both values; `make docs-figures`
# writes them all again.
#
# In make test it runs after the boards' runs, tests/check_water_cost.sh and
# tests/check_sweep.sh, and takes what they measured (--reuse): the boards' reports
# (make bench-target rebuilds nothing up to date) and the water cost's lines.
# docs/sweep/front.md, which docs/sweep.md's preset tables copy, is held to a fresh
# measurement by tests/check_sweep.sh.
# Usage: TARN_BIN=build/release/tarn tests/check_doc_figures.sh
set -u
cd "$(dirname "$0")/.." || exit 2
TARN_BIN=${TARN_BIN:-build/release/tarn} exec python3 scripts/docs_figures.py check --reuse --quiet
