/* panel_tables_internal.h: what the drivers in panel.c know about each panel model,
 * as data.
 * Internal to core/: backends use tarn_panel.h. */
#ifndef TARN_PANEL_TABLES_INTERNAL_H
#define TARN_PANEL_TABLES_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

/* An init sequence is a byte string of steps, each a command, the number of data
 * bytes that follow it, the wait in ms before the next step, then the data: packed,
 * the ILI9341's 22 steps take 105 bytes of flash instead of 396 as structs. */
#define TARN_PANEL_STEP_HEADER 3u

typedef struct {
    uint16_t width, height;      /* visible pixels in rotation 0 */
    uint8_t madctl[4];           /* per rotation */
    uint16_t column_offset[4];   /* per rotation, added to CASET */
    uint16_t row_offset[4];      /* per rotation, added to RASET */
    const uint8_t *init; /* the steps, packed */
    size_t init_bytes;
} tarn_panel_model_facts;

/* NULL for a value that names no model. */
const tarn_panel_model_facts *tarn__panel_model_facts_of(unsigned model);

#endif
