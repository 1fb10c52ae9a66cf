#include "sweep_front.h"

#include <stdlib.h>

typedef struct {
    const tarn_sweep_scene *scene;
    size_t source;
} front_order;

static front_order order; /* qsort takes no context */

/* Cheapest first; at equal cost, the more accurate first. */
static int by_cost_then_error(const void *a, const void *b)
{
    const tarn_sweep_point *p = &order.scene->points[*(const size_t *)a];
    const tarn_sweep_point *q = &order.scene->points[*(const size_t *)b];
    const double cp = p->cost[order.source], cq = q->cost[order.source];
    if (cp != cq) return cp < cq ? -1 : 1;
    if (p->error.whole.psnr_db != q->error.whole.psnr_db) return p->error.whole.psnr_db > q->error.whole.psnr_db ? -1 : 1;
    return 0;
}

size_t tarn_sweep_front(const tarn_sweep_scene *scene, size_t source, size_t *front)
{
    size_t measured = 0;
    for (size_t i = 0; i < scene->count; i++)
        if (scene->points[i].cost[source] >= 0) front[measured++] = i;
    order.scene = scene;
    order.source = source;
    qsort(front, measured, sizeof *front, by_cost_then_error);
    size_t kept = 0;
    double best = -1.0;
    for (size_t k = 0; k < measured; k++) {
        const double psnr = scene->points[front[k]].error.whole.psnr_db;
        if (psnr > best) {
            best = psnr;
            front[kept++] = front[k];
        }
    }
    return kept;
}
