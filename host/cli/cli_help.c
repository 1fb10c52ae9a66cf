/* cli_help.c: the tool's help and version (cli_help.h). */
#include "cli_help.h"

#include <string.h>

#include "gpio_lines.h"
#include "mcp2210_hidapi.h"
#include "show_options.h"
#include "sweep.h"
#include "tarn/tarn.h"
#include "view_options.h"
#include "view_state.h"
#include "view_window.h"

static const char overview[] =
    "tarn: an integer-only renderer of small 3D scenes with stylised water, for microcontrollers\n"
    "usage: tarn COMMAND [ARGUMENTS]\n"
    "  render    draw a scene with the integer core (or the float reference) to PNG\n"
    "  compare   measure the core's frame against the float reference: one line of errors\n"
    "  memory    the working memory a frame needs at a quality\n"
    "  bake      a scene as const C data for firmware, with the switches it links\n"
    "  show      stream frames to a panel: an emulator, spidev + GPIO, or an MCP2210 bridge\n"
    "  view      a window on the PC that draws the scene live: keys for time, presets and knobs\n"
    "  sweep     the speed/accuracy map of the quality knobs\n"
    "  accuracy  the core's arithmetic against double precision\n"
    "'tarn COMMAND --help' gives a command's options; 'tarn --version' this build.\n";

static const char quality_usage[] =
    "QUALITY: --quality fast|balanced|exact (a preset, balanced by default; the knobs below\n"
    "         override it wherever they stand)\n"
    "         --tile N (8..64) --subpixel N (1..8) --perspective affine|pixel|span:N (N 2..64)\n"
    "         --depth 16|32 --recip-steps N (0..2) --exp2 N[:nearest|:linear] (N 8..256)\n"
    "         --depth-interpolation exact|plane (near/d rounded exactly at each pixel, or on a\n"
    "         plane like the attributes': a division less a triangle)\n"
    "         --fog-bits N (4..16: fraction bits of the depth of water in fog's exp2)\n"
    "         --apron on|off|N (how far refraction may move a sample, so how much opaque scene\n"
    "         each tile renders around its water: as far as it reaches, not at all, or N pixels 0..32)\n"
    "         --bins on|off (find each cluster's screen box once a frame, 4 bytes a cluster)\n"
    "         --water-block 1|2|4 (water effects found at every pixel, or once per 2x2 or 4x4 block:\n"
    "         tiles a multiple of the block only)\n"
    "         --refraction-normal shared|exact (the normal refraction moves by: the highlight's\n"
    "         14 bits, or found again from the maps' texels to 2^-15)\n"
    "         --lit planes|line (per-pixel perspective: a plane for each channel of the lit colour,\n"
    "         or one where the vertices' colours lie on a line, two planes and divisions less)\n"
    "         --frame tiles|strips (square tiles, or strips of --tile rows of the whole width\n"
    "         whose opaque pass is kept for the strips below: each pixel drawn once, more memory)\n"
    "         --vertices tile|frame|frame-view (vertices found by each tile's walk, or once a frame\n"
    "         into memory: 16 bytes a vertex, 28 with the view positions clipped triangles read)\n"
    "         --water-uv plane|triangles (flat water's texture coordinates where the pixel's ray\n"
    "         meets its plane, as the reference; or interpolated on each triangle: fast's, less code)\n";

static const char backdrop_usage[] =
    "  --backdrop on|off|still  on: the opaque objects drawn once, for the frame and quality,\n"
    "               into a palette image the water draws over; the image is the same. still: the\n"
    "               water's still terms drawn into it too, and only its moving ones each frame;\n"
    "               each channel within 1 of the scene drawn whole, but for the highlights that\n"
    "               water blocks share and refracted samples (docs/bake.md); its texture\n"
    "               coordinates are the water's plane's (--water-uv plane, which still sets)\n"
    "  --landing-depth U  still: how deep (world units 1..4, 4 by default) the water kept is\n"
    "               under a pixel where a refracted sample may land within the foam band of the\n"
    "               water it moved from; shallower keeps fewer pixels (2 bytes each), and a\n"
    "               sample landing on deeper water shows no foam\n";

static const char render_usage[] =
    "usage: tarn render SCENE -o OUT.png|OUT.gif [--size WxH] [--time MS] [--frames N [--fps F]]\n"
    "                   [--camera X,Y,Z:TX,TY,TZ[:FOV]] [--reference [--snapped]]\n"
    "                   [--backdrop on|off|still [--landing-depth U]] [--rgb565] [--quiet] [QUALITY]\n"
    "  -o OUT.png   the image; - writes it to standard output. A regular file is replaced only\n"
    "               once complete, a link's target is written, a device or FIFO written through\n"
    "  -o OUT.gif   one animated GIF of the frames (one palette for all; F at most 50)\n"
    "  --size WxH   the frame (the scene's own by default)\n"
    "  --time MS    the clock: water, sparkles and camera paths move with it (0 by default)\n"
    "  --frames N   a sequence: OUT-0000.png onward, frame k at MS + k * 1000 / F (F 30 by default)\n"
    "  --camera X,Y,Z:TX,TY,TZ[:FOV]  a still camera at X,Y,Z looking at TX,TY,TZ (world units), its\n"
    "               vertical field of view FOV degrees (the scene's by default), in place of the\n"
    "               scene's camera and path; tarn view prints the one it shows\n"
    "  --reference  the float reference instead of the core; --snapped on the core's own triangles\n"
    "  --rgb565     each frame as the panel shows it: RGB565 with the boards' ordered dither\n"
    "  --quiet      no progress line on stderr\n";

static const char compare_usage[] =
    "usage: tarn compare SCENE [--size WxH] [--time MS] [--camera X,Y,Z:TX,TY,TZ[:FOV]]\n"
    "                    [--diff HEAT.png] [--backdrop on|off|still [--landing-depth U]] [QUALITY]\n"
    "  prints: compare scene= size= time= psnr= maxerr= over2= over8= shading_psnr= shading_over2=\n"
    "  panel_psnr= coverage= (docs/sweep.md says what each isolates)\n"
    "  --diff HEAT.png  the whole error as a heat map, magenta where the surface differs\n";

static const char memory_usage[] =
    "usage: tarn memory SCENE [--size WxH] [QUALITY]\n"
    "  prints the bytes a frame's working memory takes (bytes=), baked (baked_bytes=), and in\n"
    "  tiles and in strips (tiles_bytes=, strips_bytes=), and in strips shared by two workers\n"
    "  (pipeline_bytes=, tarn_strip_pipeline_begin)\n";

static const char bake_usage[] =
    "usage: tarn bake SCENE -o OUT.c [--name NAME] [--size WxH] [--points FILE]\n"
    "                 [--static-view on|off] [--backdrop on|off|still [--landing-depth U]] [--quiet] [QUALITY]\n"
    "  -o OUT.c     the scene as const C data; OUT.h and OUT_link.h are written beside it\n"
    "  --name NAME  the C name of the scene (OUT's base name by default)\n"
    "  --points FILE  more qualities the firmware may switch to, one line of knobs each\n"
    "  --static-view on|off  vertices transformed on the host once (on) or each frame (off)\n"
    "  --quiet      no progress line on stderr\n";

static const char accuracy_usage[] =
    "usage: tarn accuracy --math\n"
    "  each fixed-point function of the core (exp2, reciprocal, sine...) at each of its\n"
    "  settings against double precision: largest and mean error in units of its last place\n";

typedef struct {
    const char *name;
    const char *usage;
    int quality;  /* takes QUALITY */
    int backdrop; /* takes --backdrop */
} command_help;

static const command_help commands[] = {
    {"render", render_usage, 1, 1}, {"compare", compare_usage, 1, 1}, {"memory", memory_usage, 1, 0},
    {"bake", bake_usage, 1, 1},     {"accuracy", accuracy_usage, 0, 0},
};

/* tarn view's usage, its keys, then QUALITY. */
static int print_view_help(FILE *out)
{
    char keys[2048];
    tarn_view_key_help(keys, sizeof keys);
    return fputs(tarn_view_usage, out) < 0 || fputs(keys, out) < 0 || fputs(quality_usage, out) < 0 ? -1 : 0;
}

int tarn_cli_wants_help(int argc, char **argv)
{
    for (int i = 2; i < argc; i++)
        if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) return 1;
    return 0;
}

int tarn_cli_print_help(const char *command, FILE *out)
{
    if (command == NULL) return fputs(overview, out) < 0 ? -1 : 0;
    if (strcmp(command, "show") == 0) return fputs(tarn_show_usage, out) < 0 ? -1 : 0;
    if (strcmp(command, "sweep") == 0) return fputs(tarn_sweep_usage, out) < 0 ? -1 : 0;
    if (strcmp(command, "view") == 0) return print_view_help(out);
    for (size_t k = 0; k < sizeof commands / sizeof commands[0]; k++) {
        if (strcmp(command, commands[k].name) != 0) continue;
        fputs(commands[k].usage, out);
        if (commands[k].backdrop) fputs(backdrop_usage, out);
        if (commands[k].quality) fputs(quality_usage, out);
        return 0;
    }
    return -1;
}

/* Each TARN_LINK_* switch as this build's core has it (tarn_config.h). */
static void print_link_switches(FILE *out)
{
    static const struct {
        const char *name;
        unsigned long value;
    } switches[] = {
        {"PERSPECTIVE_AFFINE", TARN_LINK_PERSPECTIVE_AFFINE}, {"PERSPECTIVE_SPAN", TARN_LINK_PERSPECTIVE_SPAN},
        {"PERSPECTIVE_PIXEL", TARN_LINK_PERSPECTIVE_PIXEL},   {"DEPTH16", TARN_LINK_DEPTH16},
        {"DEPTH32", TARN_LINK_DEPTH32},                       {"EXACT_DEPTH", TARN_LINK_EXACT_DEPTH},
        {"COMPUTED_VERTICES", TARN_LINK_COMPUTED_VERTICES},   {"STATIC_VERTICES", TARN_LINK_STATIC_VERTICES},
        {"FOUND_BINS", TARN_LINK_FOUND_BINS},                 {"BACKDROP", TARN_LINK_BACKDROP},
        {"OPAQUE_OBJECTS", TARN_LINK_OPAQUE_OBJECTS},         {"STILL_WATER", TARN_LINK_STILL_WATER},
        {"WATER", TARN_LINK_WATER},                           {"WATER_FEATURES", TARN_LINK_WATER_FEATURES},
        {"WATER_FEATURES_ALL", TARN_LINK_WATER_FEATURES_ALL}, {"WATER_SHADING", TARN_LINK_WATER_SHADING},
        {"APRON", TARN_LINK_APRON},                           {"REFRACTION_EXACT", TARN_LINK_REFRACTION_EXACT},
        {"WATER_BLOCKS", TARN_LINK_WATER_BLOCKS},             {"STRIPS", TARN_LINK_STRIPS},
        {"VERTEX_PASS", TARN_LINK_VERTEX_PASS},               {"PARTS", TARN_LINK_PARTS},
        {"WATER_PLANE", TARN_LINK_WATER_PLANE},
    };
    fputs("link switches:", out);
    for (size_t k = 0; k < sizeof switches / sizeof switches[0]; k++)
        fprintf(out, switches[k].value <= 1 ? " %s=%lu" : " %s=0x%lX", switches[k].name, switches[k].value);
    fputs("\n", out);
}

void tarn_cli_print_version(FILE *out)
{
    fprintf(out, "tarn %s\n", tarn_version());
    print_link_switches(out);
    fprintf(out, "display backends: gpio=%s usb=%s\n", tarn_gpio_backend, tarn_mcp2210_usb_backend);
    fprintf(out, "view window: %s\n", tarn_view_window_backend());
}
