#include "error.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

/* The UTF-8 bytes of a Unicode bidirectional control at `s` (U+061C, U+200E/F,
 * U+202A..E, U+2066..9), with its code point; 0 for anything else. */
static size_t bidi_control_at(const unsigned char *s, unsigned *code_point)
{
    if (s[0] == 0xd8 && s[1] == 0x9c) {
        *code_point = 0x061c;
        return 2;
    }
    if (s[0] != 0xe2 || s[1] < 0x80 || s[1] > 0x81 || s[2] < 0x80 || s[2] > 0xbf) return 0;
    *code_point = 0x2000u | (unsigned)(s[1] & 0x3f) << 6 | (unsigned)(s[2] & 0x3f);
    const int bidi = *code_point == 0x200e || *code_point == 0x200f ||
                     (*code_point >= 0x202a && *code_point <= 0x202e) ||
                     (*code_point >= 0x2066 && *code_point <= 0x2069);
    return bidi ? 3 : 0;
}

void tarn_escape_text(const char *text, char *out, size_t size)
{
    size_t used = 0;
    char piece[8];
    for (const unsigned char *s = (const unsigned char *)text; *s != '\0';) {
        unsigned code_point;
        size_t bidi = bidi_control_at(s, &code_point);
        size_t taken = 1;
        if (bidi) {
            snprintf(piece, sizeof piece, "\\u%04X", code_point);
            taken = bidi;
        } else if (*s < 0x20 || *s == 0x7f) {
            snprintf(piece, sizeof piece, "\\x%02x", *s);
        } else {
            piece[0] = (char)*s;
            piece[1] = '\0';
        }
        size_t length = strlen(piece);
        if (used + length >= size) break;
        memcpy(out + used, piece, length);
        used += length;
        s += taken;
    }
    out[used] = '\0';
}

int tarn_fail(tarn_error *err, const char *format, ...)
{
    if (err == NULL) return -1;
    char raw[TARN_ERROR_MESSAGE_MAX];
    va_list args;
    va_start(args, format);
    vsnprintf(raw, sizeof raw, format, args);
    va_end(args);
    tarn_escape_text(raw, err->message, sizeof err->message);
    return -1;
}

int tarn_fail_in(tarn_error *err, const char *path)
{
    if (err == NULL) return -1;
    tarn_error inner = *err;
    return tarn_fail(err, "%s: %s", path, inner.message);
}
