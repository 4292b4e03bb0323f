/*
 * Rays at the ground for the range sensors: the heightfield walked cell by cell along the ray (a 2-D DDA over the
 * grid, the two triangles of each cell tested, the same triangulation as MuJoCo's heightfield), then the intact
 * fragile cells. Why not mj_ray: in MuJoCo 2.2.2 a heightfield ray tests every cell in the rectangle its
 * projection spans, so a long diagonal ray over a tall heightfield costs up to ~130 µs — several in one tick
 * overran the 1 ms period. This walk visits only the cells under the ray, up to the sensor's range (≤ ~2 µs).
 * RangeSensorTest checks it against mj_ray. One difference, on purpose: at the course's border MuJoCo's heightfield
 * has side walls up to its full elevation range; here a ray meets the border only below the surface there.
 * No allocation, no system call.
 */
#include <math.h>
#include "roq_sim.h"

/* Möller–Trumbore: distance along the ray to triangle (a, b, c), or -1. */
static double triangle(const mjtNum o[3], const mjtNum v[3], const double a[3], const double b[3], const double c[3]) {
    double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    double e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    double p[3] = {v[1] * e2[2] - v[2] * e2[1], v[2] * e2[0] - v[0] * e2[2], v[0] * e2[1] - v[1] * e2[0]};
    double det = e1[0] * p[0] + e1[1] * p[1] + e1[2] * p[2];
    if (fabs(det) < 1e-12) {
        return -1;
    }
    double inv = 1.0 / det;
    double t0[3] = {o[0] - a[0], o[1] - a[1], o[2] - a[2]};
    double u = (t0[0] * p[0] + t0[1] * p[1] + t0[2] * p[2]) * inv;
    if (u < 0 || u > 1) {
        return -1;
    }
    double q[3] = {t0[1] * e1[2] - t0[2] * e1[1], t0[2] * e1[0] - t0[0] * e1[2], t0[0] * e1[1] - t0[1] * e1[0]};
    double w = (v[0] * q[0] + v[1] * q[1] + v[2] * q[2]) * inv;
    if (w < 0 || u + w > 1) {
        return -1;
    }
    double t = (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) * inv;
    return t >= 0 ? t : -1;
}

/* The nearer hit of the two triangles of cell (r, c), in world coordinates, or -1. */
static double cell(const roq_model *model, int r, int c, const mjtNum o[3], const mjtNum v[3]) {
    const mjModel *m = model->m;
    int g = model->terrain_geom;
    int h = m->geom_dataid[g];
    int ncol = m->hfield_ncol[h];
    const float *data = m->hfield_data + m->hfield_adr[h];
    const mjtNum *size = m->hfield_size + 4 * h;
    const mjtNum *pos = m->geom_pos + 3 * g;
    double dx = 2 * size[0] / (ncol - 1);
    double dy = 2 * size[1] / (m->hfield_nrow[h] - 1);
    double x0 = pos[0] - size[0] + c * dx, y0 = pos[1] - size[1] + r * dy;
    double p00[3] = {x0, y0, pos[2] + data[r * ncol + c] * size[2]};
    double p11[3] = {x0 + dx, y0 + dy, pos[2] + data[(r + 1) * ncol + c + 1] * size[2]};
    double p10[3] = {x0 + dx, y0, pos[2] + data[r * ncol + c + 1] * size[2]};
    double p01[3] = {x0, y0 + dy, pos[2] + data[(r + 1) * ncol + c] * size[2]};
    double t1 = triangle(o, v, p00, p11, p10);
    double t2 = triangle(o, v, p00, p11, p01);
    if (t1 < 0) {
        return t2;
    }
    return (t2 < 0 || t1 < t2) ? t1 : t2;
}

/* Surface height at grid-frame point (x, y), bilinear within its cell (exact along the grid's border edges). */
static double surface(const roq_model *model, double x, double y) {
    const mjModel *m = model->m;
    int g = model->terrain_geom;
    int h = m->geom_dataid[g];
    int nrow = m->hfield_nrow[h], ncol = m->hfield_ncol[h];
    const float *data = m->hfield_data + m->hfield_adr[h];
    const mjtNum *size = m->hfield_size + 4 * h;
    double fx = x / (2 * size[0] / (ncol - 1)), fy = y / (2 * size[1] / (nrow - 1));
    int c = (int)floor(fx), r = (int)floor(fy);
    c = c < 0 ? 0 : (c > ncol - 2 ? ncol - 2 : c);
    r = r < 0 ? 0 : (r > nrow - 2 ? nrow - 2 : r);
    double tx = fx - c, ty = fy - r;
    double a = data[r * ncol + c] * (1 - tx) + data[r * ncol + c + 1] * tx;
    double b = data[(r + 1) * ncol + c] * (1 - tx) + data[(r + 1) * ncol + c + 1] * tx;
    return m->geom_pos[3 * g + 2] + (a * (1 - ty) + b * ty) * size[2];
}

/* A ray crossing the grid's border below the surface meets the heightfield's side wall (as in MuJoCo). */
static int through_wall(const roq_model *model, const mjtNum o[3], const mjtNum v[3], double t, double ox, double oy) {
    return o[2] + v[2] * t < surface(model, ox + v[0] * t, oy + v[1] * t);
}

static double terrain(const roq_model *model, const mjtNum o[3], const mjtNum v[3], double max_range) {
    const mjModel *m = model->m;
    int g = model->terrain_geom;
    int h = m->geom_dataid[g];
    int nrow = m->hfield_nrow[h], ncol = m->hfield_ncol[h];
    const mjtNum *size = m->hfield_size + 4 * h;
    const mjtNum *pos = m->geom_pos + 3 * g;
    double dx = 2 * size[0] / (ncol - 1), dy = 2 * size[1] / (nrow - 1);
    double W = 2 * size[0], H = 2 * size[1];
    double ox = o[0] - pos[0] + size[0], oy = o[1] - pos[1] + size[1]; /* grid frame: (0,0) at row 0, col 0 */
    double lo = 0, hi = max_range;
    double org[2] = {ox, oy}, dir[2] = {v[0], v[1]}, ext[2] = {W, H};
    for (int k = 0; k < 2; k++) { /* clip [lo, hi] to the grid's rectangle */
        if (fabs(dir[k]) < 1e-15) {
            if (org[k] < 0 || org[k] > ext[k]) {
                return -1;
            }
            continue;
        }
        double a = (0 - org[k]) / dir[k], b = (ext[k] - org[k]) / dir[k];
        if (a > b) {
            double t = a; a = b; b = t;
        }
        lo = fmax(lo, a);
        hi = fmin(hi, b);
    }
    if (lo > hi) {
        return -1;
    }
    if (lo > 0 && through_wall(model, o, v, lo, ox, oy)) {
        return lo;
    }
    int leaves = hi < max_range; /* the ray leaves the grid within range: it may meet the far wall */
    double x = ox + v[0] * lo, y = oy + v[1] * lo;
    int c = (int)floor(x / dx), r = (int)floor(y / dy);
    c = c < 0 ? 0 : (c > ncol - 2 ? ncol - 2 : c);
    r = r < 0 ? 0 : (r > nrow - 2 ? nrow - 2 : r);
    int step_c = v[0] > 0 ? 1 : -1, step_r = v[1] > 0 ? 1 : -1;
    double next_x = fabs(v[0]) < 1e-15 ? INFINITY : ((c + (v[0] > 0)) * dx - ox) / v[0];
    double next_y = fabs(v[1]) < 1e-15 ? INFINITY : ((r + (v[1] > 0)) * dy - oy) / v[1];
    double delta_x = fabs(v[0]) < 1e-15 ? INFINITY : dx / fabs(v[0]);
    double delta_y = fabs(v[1]) < 1e-15 ? INFINITY : dy / fabs(v[1]);
    for (;;) {
        double t = cell(model, r, c, o, v);
        if (t >= 0) {
            return t <= max_range ? t : -1;
        }
        if (next_x < next_y) {
            if (next_x > hi) {
                break;
            }
            c += step_c;
            next_x += delta_x;
        } else {
            if (next_y > hi) {
                break;
            }
            r += step_r;
            next_y += delta_y;
        }
        if (c < 0 || c > ncol - 2 || r < 0 || r > nrow - 2) {
            break;
        }
    }
    return leaves && through_wall(model, o, v, hi, ox, oy) ? hi : -1;
}

double roq_ground_ray(const roq_model *model, const roq_state *state, const mjtNum pnt[3], const mjtNum vec[3],
                      double max_range) {
    double best = terrain(model, pnt, vec, max_range);
    for (int i = 0; i < model->nfragile; i++) {
        if (state->cell[i].broken) {
            continue;
        }
        int g = model->fragile[i].geom;
        mjtNum t = mju_rayGeom(state->d->geom_xpos + 3 * g, state->d->geom_xmat + 9 * g, model->m->geom_size + 3 * g,
                               pnt, vec, mjGEOM_BOX);
        if (t >= 0 && t <= max_range && (best < 0 || t < best)) {
            best = t;
        }
    }
    return best;
}
