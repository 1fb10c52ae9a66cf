#include "link_counts.h"

#include <errno.h>
#include <time.h>

int tarn_sleep_ms(void *user, uint16_t milliseconds)
{
    (void)user;
    struct timespec wait = {milliseconds / 1000, (long)(milliseconds % 1000) * 1000000L};
    while (nanosleep(&wait, &wait) != 0 && errno == EINTR) {
    }
    return 0;
}
