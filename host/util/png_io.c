#include "png_io.h"

#include <errno.h>
#include <png.h>
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "atomic_file.h"
#include "input_file.h"
#include "tarn/tarn_scene.h"

/* Everything one libpng run owns. libpng reports errors by longjmp, so all of it
 * lives here, outside the frame that calls setjmp, and is released by one cleanup
 * whichever way the run ends. */
typedef struct {
    const char *path;
    FILE *file;
    png_structp png;
    png_infop info;
    uint8_t *pixels;
    char message[256]; /* libpng's (or our I/O) reason for the longjmp */
} png_job;

static void on_png_error(png_structp png, png_const_charp message)
{
    png_job *job = png_get_error_ptr(png);
    snprintf(job->message, sizeof job->message, "%s", message);
    png_longjmp(png, 1);
}

/* Warnings (bad ancillary chunk CRCs, odd gamma...) do not stop a read, and the
 * tool's stderr is reserved for its one-line error. */
static void on_png_warning(png_structp png, png_const_charp message)
{
    (void)png;
    (void)message;
}

static void read_bytes(png_structp png, png_bytep data, size_t length)
{
    png_job *job = png_get_io_ptr(png);
    if (fread(data, 1, length, job->file) == length) return;
    if (ferror(job->file)) png_error(png, strerror(errno));
    png_error(png, "file is truncated");
}

static void write_bytes(png_structp png, png_bytep data, size_t length)
{
    png_job *job = png_get_io_ptr(png);
    if (fwrite(data, 1, length, job->file) != length) png_error(png, strerror(errno));
}

static void flush_bytes(png_structp png)
{
    png_job *job = png_get_io_ptr(png);
    if (fflush(job->file) != 0) png_error(png, strerror(errno));
}

/* Frees what a read job holds except the pixels, which a successful read hands on. */
static void read_job_close(png_job *job)
{
    if (job->png) png_destroy_read_struct(&job->png, job->info ? &job->info : NULL, NULL);
    if (job->file) fclose(job->file);
    job->png = NULL;
    job->info = NULL;
    job->file = NULL;
}

/* Checks the size from the header; returns 0 or fails with a message. */
typedef int (*size_check)(const char *path, uint32_t width, uint32_t height, tarn_error *err);

/* Decodes the opened job's image as `channels` 8-bit channels into job->pixels.
 * Only this function calls setjmp, so the jump never crosses a live frame. */
static int decode(png_job *job, unsigned channels, size_check check, tarn_image *out,
                  tarn_error *err)
{
    if (setjmp(png_jmpbuf(job->png))) {
        return tarn_fail(err, "%s: bad PNG: %s", job->path, job->message);
    }
    png_set_read_fn(job->png, job, read_bytes);
    png_set_sig_bytes(job->png, 8);
    png_read_info(job->png, job->info);

    uint32_t width = png_get_image_width(job->png, job->info);
    uint32_t height = png_get_image_height(job->png, job->info);
    if (check(job->path, width, height, err)) return -1;

    int colour_type = png_get_color_type(job->png, job->info);
    png_set_expand(job->png); /* palette -> RGB, gray < 8 bits -> 8 bits, tRNS -> alpha */
    png_set_strip_16(job->png);
    png_set_strip_alpha(job->png);
    if (channels == 1 && (colour_type & PNG_COLOR_MASK_COLOR)) {
        png_set_rgb_to_gray_fixed(job->png, 1, -1, -1); /* 1: convert silently */
    } else if (channels == 3 && !(colour_type & PNG_COLOR_MASK_COLOR)) {
        png_set_gray_to_rgb(job->png);
    }
    int passes = png_set_interlace_handling(job->png);
    png_read_update_info(job->png, job->info);
    size_t stride = (size_t)width * channels;
    if (png_get_rowbytes(job->png, job->info) != stride) {
        return tarn_fail(err, "%s: unsupported PNG layout", job->path);
    }

    job->pixels = calloc((size_t)height, stride);
    if (!job->pixels) {
        return tarn_fail(err, "%s: out of memory for a %ux%u image", job->path, width, height);
    }
    for (int pass = 0; pass < passes; pass++) {
        for (uint32_t y = 0; y < height; y++) {
            png_read_row(job->png, job->pixels + y * stride, NULL);
        }
    }
    /* Reading through IEND catches files cut off after the image data. */
    png_read_end(job->png, NULL);

    out->width = (uint16_t)width;
    out->height = (uint16_t)height;
    out->channels = (uint8_t)channels;
    out->pixels = job->pixels;
    job->pixels = NULL;
    return 0;
}

static int read_png(const char *path, unsigned channels, size_check check, tarn_image *out,
                    tarn_error *err)
{
    memset(out, 0, sizeof *out);
    png_job job;
    memset(&job, 0, sizeof job);
    job.path = path;
    job.file = tarn_open_input(path, "a PNG file", TARN_PNG_FILE_BYTES_MAX, err);
    if (!job.file) return -1;

    unsigned char signature[8];
    size_t got = fread(signature, 1, sizeof signature, job.file);
    int result;
    if (ferror(job.file)) {
        result = tarn_fail(err, "%s: cannot read: %s", path, strerror(errno));
    } else if (got < sizeof signature || png_sig_cmp(signature, 0, sizeof signature) != 0) {
        result = tarn_fail(err, "%s: not a PNG file", path);
    } else {
        job.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &job, on_png_error, on_png_warning);
        if (job.png) job.info = png_create_info_struct(job.png);
        result = job.info ? decode(&job, channels, check, out, err)
                          : tarn_fail(err, "%s: out of memory", path);
    }
    free(job.pixels); /* non-NULL only when decoding failed part way */
    read_job_close(&job);
    return result;
}

static int is_power_of_two(uint32_t v)
{
    return v != 0 && (v & (v - 1)) == 0;
}

static int check_texture_size(const char *path, uint32_t width, uint32_t height, tarn_error *err)
{
    if (is_power_of_two(width) && is_power_of_two(height) && width <= TARN_TEXTURE_SIZE_MAX &&
        height <= TARN_TEXTURE_SIZE_MAX) {
        return 0;
    }
    return tarn_fail(err, "%s: texture is %ux%u; expected power-of-two sides up to %u", path,
                     width, height, TARN_TEXTURE_SIZE_MAX);
}

static int check_heightfield_size(const char *path, uint32_t width, uint32_t height,
                                  tarn_error *err)
{
    if (width < 2 || height < 2 || width > TARN_HEIGHTFIELD_SIZE_MAX || height > TARN_HEIGHTFIELD_SIZE_MAX)
        return tarn_fail(err, "%s: heightfield image is %ux%u; expected sides 2..%u", path, width,
                         height, TARN_HEIGHTFIELD_SIZE_MAX);
    const uint32_t triangles = 2u * (width - 1u) * (height - 1u);
    if (triangles > TARN_MESH_TRIANGLES_MAX)
        return tarn_fail(err, "%s: heightfield image is %ux%u, whose grid needs %u triangles; a tarn mesh "
                         "holds at most %u (a square image up to 182x182)", path, width, height, triangles,
                         TARN_MESH_TRIANGLES_MAX);
    return 0;
}

int tarn_png_read_texture(const char *path, tarn_image *out, tarn_error *err)
{
    return read_png(path, 3, check_texture_size, out, err);
}

int tarn_png_read_heightfield(const char *path, tarn_image *out, tarn_error *err)
{
    return read_png(path, 1, check_heightfield_size, out, err);
}

void tarn_image_free(tarn_image *image)
{
    if (!image) return;
    free(image->pixels);
    memset(image, 0, sizeof *image);
}

/* ---- writing ---------------------------------------------------------------- */

static int encode(png_job *job, const uint8_t *rgb, uint32_t width, uint32_t height,
                  tarn_error *err)
{
    if (setjmp(png_jmpbuf(job->png))) {
        return tarn_fail(err, "%s: cannot write PNG: %s", job->path, job->message);
    }
    png_set_write_fn(job->png, job, write_bytes, flush_bytes);
    png_set_IHDR(job->png, job->info, width, height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(job->png, job->info);
    for (uint32_t y = 0; y < height; y++) {
        png_write_row(job->png, rgb + (size_t)y * width * 3);
    }
    png_write_end(job->png, NULL);
    png_write_flush(job->png);
    return 0;
}

int tarn_png_write_rgb(const char *path, const uint8_t *rgb, uint32_t width, uint32_t height,
                       tarn_error *err)
{
    if (width == 0 || height == 0 || width > PNG_USER_WIDTH_MAX || height > PNG_USER_HEIGHT_MAX) {
        return tarn_fail(err, "%s: cannot write a %ux%u image", path, width, height);
    }
    tarn_atomic_file out;
    if (tarn_atomic_open(&out, path, err) != 0) return -1;
    png_job job;
    memset(&job, 0, sizeof job);
    job.path = path;
    job.file = out.file;
    job.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &job, on_png_error, on_png_warning);
    if (job.png) job.info = png_create_info_struct(job.png);
    int result = job.info ? encode(&job, rgb, width, height, err)
                          : tarn_fail(err, "%s: out of memory", path);
    if (job.png) png_destroy_write_struct(&job.png, job.info ? &job.info : NULL);
    if (result != 0) {
        tarn_atomic_abandon(&out);
        return -1;
    }
    return tarn_atomic_commit(&out, err);
}
