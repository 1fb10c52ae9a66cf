/* panel_tables.h: what the drivers in panel.c know about each panel model, as data.
 * Internal to core/: backends use tarn_panel.h. */
#ifndef TARN_PANEL_TABLES_H
#define TARN_PANEL_TABLES_H

#include <stddef.h>
#include <stdint.h>

#define TARN_PANEL_STEP_DATA_MAX 15u /* the longest parameter list: ILI9341's gamma curves */

/* One command of an init sequence and the wait after it. */
typedef struct {
    uint8_t command;
    uint8_t length;   /* data bytes that follow the command */
    uint8_t delay_ms; /* wait before the next command */
    uint8_t data[TARN_PANEL_STEP_DATA_MAX];
} tarn_panel_init_step;

typedef struct {
    uint16_t width, height;      /* visible pixels in rotation 0 */
    uint8_t madctl[4];           /* per rotation */
    uint16_t column_offset[4];   /* per rotation, added to CASET */
    uint16_t row_offset[4];      /* per rotation, added to RASET */
    const tarn_panel_init_step *init;
    size_t init_steps;
} tarn_panel_model_facts;

/* NULL for a value that names no model. */
const tarn_panel_model_facts *tarn_panel_model_facts_of(unsigned model);

#endif
