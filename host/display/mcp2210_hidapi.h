/* mcp2210_hidapi.h: the MCP2210 seam on a real bridge through hidapi (hidraw).
 * Implemented by mcp2210_hidapi.c, or by mcp2210_hidapi_none.c in a build without
 * hidapi, which says so. */
#ifndef TARN_HOST_MCP2210_HIDAPI_H
#define TARN_HOST_MCP2210_HIDAPI_H

#include "error.h"
#include "mcp2210.h"

#define TARN_MCP2210_VENDOR_ID 0x04D8u  /* Microchip */
#define TARN_MCP2210_PRODUCT_ID 0x00DEu

typedef struct tarn_mcp2210_usb tarn_mcp2210_usb;

/* The backend this build has: "hidapi-hidraw", or "none" (tarn --version). */
extern const char tarn_mcp2210_usb_backend[];

/* Opens the first MCP2210, or the one with this serial number (NULL: any). 0, or
 * -1 with one line saying none is attached, or why it cannot be opened. */
int tarn_mcp2210_usb_open(const char *serial, tarn_mcp2210_usb **usb, tarn_mcp2210_seam *seam,
                          tarn_error *err);

/* Closes the device and hidapi; NULL is fine. */
void tarn_mcp2210_usb_close(tarn_mcp2210_usb *usb);

#endif
