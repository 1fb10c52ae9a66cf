/* panel_link.c: the panel transport every wire-driving backend shares (panel_link.h). */
#include "panel_link.h"

tarn_panel_link tarn_panel_link_make(tarn_link_send_fn send)
{
    tarn_panel_link link = {send, NULL, tarn_sleep_ms, NULL, {0, 0, 0, 0}, {{0}}};
    return link;
}

static int link_command(void *user, uint8_t command)
{
    tarn_panel_link *link = user;
    return link->send(link, 0, &command, 1);
}

static int link_data(void *user, const uint8_t *bytes, size_t count)
{
    tarn_panel_link *link = user;
    return link->send(link, 1, bytes, count);
}

static int link_reset(void *user, int asserted)
{
    tarn_panel_link *link = user;
    return link->reset(link, asserted);
}

static int link_delay(void *user, uint16_t milliseconds)
{
    tarn_panel_link *link = user;
    return link->delay(link->delay_user, milliseconds);
}

tarn_panel_transport tarn_panel_link_transport(tarn_panel_link *link)
{
    tarn_panel_transport t = {link, link_command, link_data, link->reset ? link_reset : NULL, link_delay};
    return t;
}

static int counted_send(tarn_panel_link *link, int dc, const uint8_t *bytes, size_t count)
{
    tarn_counted_link *c = (tarn_counted_link *)link; /* the link is its first member */
    link->counts.spi_bytes += count;
    link->counts.transfers++;
    link->counts.link_ns += tarn_link_ns(count, c->hz);
    return dc ? c->panel.data(c->panel.user, bytes, count) : c->panel.command(c->panel.user, bytes[0]);
}

static int counted_reset(tarn_panel_link *link, int asserted)
{
    tarn_counted_link *c = (tarn_counted_link *)link;
    return c->panel.reset(c->panel.user, asserted);
}

void tarn_counted_link_init(tarn_counted_link *counted, tarn_panel_transport panel, uint32_t hz)
{
    counted->link = tarn_panel_link_make(counted_send);
    counted->link.reset = counted_reset;
    counted->link.delay = panel.delay_ms;
    counted->link.delay_user = panel.user;
    counted->panel = panel;
    counted->hz = hz;
}
