/* mcp2210_hidapi.c: the MCP2210 seam through hidapi: hid_open by vendor, product and
 * serial, hid_write of the 64-byte report behind a report number 0 (the bridge has
 * no numbered reports, so hidapi wants a leading 0), hid_read_timeout. */
#include "mcp2210_hidapi.h"

#include <hidapi.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <wchar.h>

const char tarn_mcp2210_usb_backend[] = "hidapi-hidraw";

struct tarn_mcp2210_usb {
    hid_device *device;
};

static int usb_write(void *user, const uint8_t report[TARN_MCP2210_REPORT_BYTES])
{
    tarn_mcp2210_usb *usb = user;
    unsigned char out[TARN_MCP2210_REPORT_BYTES + 1] = {0};
    memcpy(out + 1, report, TARN_MCP2210_REPORT_BYTES);
    return hid_write(usb->device, out, sizeof out) == (int)sizeof out ? 0 : -1;
}

static int usb_read(void *user, uint8_t report[TARN_MCP2210_REPORT_BYTES], int timeout_ms)
{
    tarn_mcp2210_usb *usb = user;
    int got = hid_read_timeout(usb->device, report, TARN_MCP2210_REPORT_BYTES, timeout_ms);
    if (got < 0) return -1;
    return got == 0 ? 0 : (int)TARN_MCP2210_REPORT_BYTES;
}

int tarn_mcp2210_usb_open(const char *serial, tarn_mcp2210_usb **usb, tarn_mcp2210_seam *seam,
                          tarn_error *err)
{
    *usb = NULL;
    if (hid_init() != 0) return tarn_fail(err, "mcp2210: cannot start hidapi (check /dev/hidraw* permissions)");
    wchar_t wide[64];
    if (serial != NULL && mbstowcs(wide, serial, 63) == (size_t)-1) {
        hid_exit();
        return tarn_fail(err, "mcp2210:%s: the serial number is not valid text", serial);
    }
    wide[63] = L'\0';
    struct hid_device_info *found =
        hid_enumerate(TARN_MCP2210_VENDOR_ID, TARN_MCP2210_PRODUCT_ID);
    int attached = found != NULL;
    hid_free_enumeration(found);
    if (!attached) {
        hid_exit();
        return tarn_fail(err, "mcp2210: no MCP2210 attached (check lsusb for 04d8:00de and the cable)");
    }
    hid_device *device = hid_open(TARN_MCP2210_VENDOR_ID, TARN_MCP2210_PRODUCT_ID, serial ? wide : NULL);
    if (device == NULL) {
        hid_exit();
        if (serial != NULL)
            return tarn_fail(err, "mcp2210:%s: no MCP2210 with this serial, or no permission (check lsusb -v and "
                             "the udev rule for /dev/hidraw*)", serial);
        return tarn_fail(err, "mcp2210: cannot open the MCP2210 (check the udev rule for /dev/hidraw*)");
    }
    *usb = calloc(1, sizeof **usb);
    if (*usb == NULL) {
        hid_close(device);
        hid_exit();
        return tarn_fail(err, "mcp2210: out of memory");
    }
    (*usb)->device = device;
    seam->user = *usb;
    seam->write = usb_write;
    seam->read = usb_read;
    return 0;
}

void tarn_mcp2210_usb_close(tarn_mcp2210_usb *usb)
{
    if (usb == NULL) return;
    hid_close(usb->device);
    free(usb);
    hid_exit();
}
