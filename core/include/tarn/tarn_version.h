/* tarn_version.h: which tarn this is.
 *
 * Semantic versioning: a new MAJOR changes the API or the meaning of scene data in
 * ways that break code written for the last one; while MAJOR is 0, a new MINOR may.
 * PATCH changes neither. The images a given scene and quality give may change in
 * any release that says so (tests/golden/frames.txt records them). */
#ifndef TARN_VERSION_H
#define TARN_VERSION_H

#define TARN_VERSION_MAJOR 0
#define TARN_VERSION_MINOR 1
#define TARN_VERSION_PATCH 0

#define TARN_VERSION_STRINGIFY_(x) #x
#define TARN_VERSION_STRINGIFY(x) TARN_VERSION_STRINGIFY_(x)
/* "MAJOR.MINOR.PATCH" */
#define TARN_VERSION_STRING                                                                        \
    TARN_VERSION_STRINGIFY(TARN_VERSION_MAJOR) "." TARN_VERSION_STRINGIFY(TARN_VERSION_MINOR) "." \
    TARN_VERSION_STRINGIFY(TARN_VERSION_PATCH)

/* MAJOR * 10000 + MINOR * 100 + PATCH, for comparisons in #if. */
#define TARN_VERSION_NUMBER (TARN_VERSION_MAJOR * 10000 + TARN_VERSION_MINOR * 100 + TARN_VERSION_PATCH)

#ifdef __cplusplus
extern "C" {
#endif

/* The version of the library linked: TARN_VERSION_STRING as it was compiled, to
 * compare with the headers a program was compiled against. */
const char *tarn_version(void);

#ifdef __cplusplus
}
#endif

#endif
