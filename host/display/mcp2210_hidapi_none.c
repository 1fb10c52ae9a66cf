/* mcp2210_hidapi_none.c: the build found no hidapi; opening a bridge says so. */
#include "mcp2210_hidapi.h"

#include <stddef.h>

const char tarn_mcp2210_usb_backend[] = "none";

int tarn_mcp2210_usb_open(const char *serial, tarn_mcp2210_usb **usb, tarn_mcp2210_seam *seam,
                          tarn_error *err)
{
    (void)serial;
    (void)seam;
    *usb = NULL;
    return tarn_fail(err, "mcp2210: this tarn was built without hidapi (install libhidapi-dev and rebuild)");
}

void tarn_mcp2210_usb_close(tarn_mcp2210_usb *usb)
{
    (void)usb;
}
