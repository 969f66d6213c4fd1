/* model_wire.c - the model importer's result on the pipe (model_wire.h): written by the
 * child in one pass after a counting pass (so its length leads), read by the parent with a
 * deadline, every count checked before it is allocated. */
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <poll.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "scene/model_wire.h"

double ssg_wire_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

/* ---- the child's side ---- */

/* Where the result goes: a descriptor, or nowhere (fd < 0) to count its bytes. */
struct sink {
    int fd;
    unsigned long long bytes;
    int broken;
};

static void put(struct sink *k, const void *p, size_t n)
{
    k->bytes += n;
    for (const char *c = p; k->fd >= 0 && !k->broken && n;) {
        ssize_t w = write(k->fd, c, n);
        if (w < 0 && errno == EINTR)
            continue;
        if (w <= 0) {
            k->broken = 1;
            break;
        }
        c += w;
        n -= (size_t)w;
    }
}

static void put_int(struct sink *k, long long v)
{
    int64_t x = v;
    put(k, &x, sizeof x);
}

static void put_mesh(struct sink *k, const struct ssg_mesh *m)
{
    size_t v = (size_t)m->vertex_count, t = (size_t)m->triangle_count;
    put_int(k, m->vertex_count);
    put_int(k, m->triangle_count);
    put_int(k, m->material);
    put_int(k, m->normals != NULL);
    put_int(k, m->uvs != NULL);
    put_int(k, m->colors != NULL);
    put(k, m->positions, 3 * v * sizeof(float));
    if (m->normals)
        put(k, m->normals, 3 * v * sizeof(float));
    if (m->uvs)
        put(k, m->uvs, 2 * v * sizeof(float));
    if (m->colors)
        put(k, m->colors, 3 * v * sizeof(float));
    put(k, m->indices, 3 * t * sizeof(uint32_t));
}

static void put_model(struct sink *k, const struct ssg_gltf *g)
{
    put_int(k, g->mesh_count);
    for (int i = 0; i < g->mesh_count; i++)
        put_mesh(k, &g->meshes[i]);
    put_int(k, g->material_count);
    put(k, g->materials, (size_t)g->material_count * sizeof *g->materials);
    put_int(k, g->texture_count);
    for (int i = 0; i < g->texture_count; i++) {
        const struct ssg_texture *t = &g->textures[i];
        put_int(k, t->width);
        put_int(k, t->height);
        put(k, t->rgb, 3 * (size_t)t->width * (size_t)t->height * sizeof(float));
        put_int(k, t->alpha != NULL);
        if (t->alpha)
            put(k, t->alpha, (size_t)t->width * (size_t)t->height * sizeof(float));
    }
    put_int(k, g->light_count);
    put(k, g->lights, (size_t)g->light_count * sizeof *g->lights);
    put_int(k, g->has_camera);
    put(k, &g->camera, sizeof g->camera);
    put(k, g->ignored, sizeof g->ignored);
}

static void put_result(struct sink *k, enum ssg_err code, const char *why,
                       const struct ssg_model_up *up, const struct ssg_gltf *g)
{
    size_t n = strlen(why);
    put_int(k, code);
    put_int(k, (long long)n);
    put(k, why, n);
    put(k, up, sizeof *up);
    put_int(k, g != NULL);
    if (g)
        put_model(k, g);
}

int ssg_wire_send(int fd, enum ssg_err code, const char *why, const struct ssg_model_up *up,
                  const struct ssg_gltf *g)
{
    struct sink count = {-1, 0, 0}, out = {fd, 0, 0};
    put_result(&count, code, why, up, g);
    put_int(&out, (long long)count.bytes);
    put_result(&out, code, why, up, g);
    return !out.broken;
}

/* ---- the parent's side ---- */

static int fail(struct ssg_wire *w, enum ssg_wire_ending how)
{
    if (w->ending == SSG_WIRE_OK)
        w->ending = how;
    return 0;
}

/* Waits until the pipe has bytes (or hangs up). Wakes every 200 ms to look for the child
   with waitpid: another thread's child may hold a copy of this pipe's write end (both were
   forked from this process), and then a dead child's end shows no hang-up. */
static int wait_readable(struct ssg_wire *w)
{
    for (;;) {
        int ms = 200;
        if (w->deadline > 0) {
            double left = w->deadline - ssg_wire_now();
            if (left <= 0)
                return fail(w, SSG_WIRE_TIMEOUT);
            ms = left < 0.2 ? (int)ceil(left * 1000.0) : ms;
        }
        struct pollfd p = {.fd = w->fd, .events = POLLIN};
        int k = poll(&p, 1, w->reaped ? 0 : ms);
        if (k > 0)
            return 1;
        if (k < 0 && errno != EINTR)
            return fail(w, SSG_WIRE_ENDED);
        if (k == 0 && w->reaped) /* it wrote all it ever will before it ended */
            return fail(w, SSG_WIRE_ENDED);
        if (!w->reaped && waitpid(w->pid, &w->status, WNOHANG) == w->pid)
            w->reaped = 1;
    }
}

static int get(struct ssg_wire *w, void *p, size_t n)
{
    if (n > w->left)
        return fail(w, SSG_WIRE_CORRUPT);
    for (char *c = p; n;) {
        if (!wait_readable(w))
            return 0;
        ssize_t r = read(w->fd, c, n);
        if (r < 0 && errno == EINTR)
            continue;
        if (r <= 0)
            return fail(w, SSG_WIRE_ENDED);
        c += r;
        n -= (size_t)r;
        w->left -= (unsigned long long)r;
    }
    return 1;
}

/* An integer in [lo, hi]. */
static int get_int(struct ssg_wire *w, long long lo, long long hi, long long *v)
{
    int64_t x;
    if (!get(w, &x, sizeof x))
        return 0;
    *v = x;
    return x >= lo && x <= hi ? 1 : fail(w, SSG_WIRE_CORRUPT);
}

/* n items of size bytes into a new array (NULL for none); 0 on failure. */
static int get_array(struct ssg_wire *w, size_t n, size_t size, void **out)
{
    *out = NULL;
    if (!n)
        return 1;
    if (n > w->left / size)
        return fail(w, SSG_WIRE_CORRUPT);
    if (!(*out = malloc(n * size)))
        return fail(w, SSG_WIRE_NOMEM);
    return get(w, *out, n * size);
}

static int get_mesh(struct ssg_wire *w, struct ssg_mesh *m)
{
    long long v, t, material, normals, uvs, colors;
    if (!get_int(w, 0, INT_MAX / 3, &v) || !get_int(w, 0, INT_MAX / 3, &t) ||
        !get_int(w, -1, INT_MAX, &material) || !get_int(w, 0, 1, &normals) ||
        !get_int(w, 0, 1, &uvs) || !get_int(w, 0, 1, &colors))
        return 0;
    m->vertex_count = (int)v;
    m->triangle_count = (int)t;
    m->material = (int)material;
    if (!get_array(w, 3 * (size_t)v, sizeof(float), (void **)&m->positions) ||
        (normals && !get_array(w, 3 * (size_t)v, sizeof(float), (void **)&m->normals)) ||
        (uvs && !get_array(w, 2 * (size_t)v, sizeof(float), (void **)&m->uvs)) ||
        (colors && !get_array(w, 3 * (size_t)v, sizeof(float), (void **)&m->colors)) ||
        !get_array(w, 3 * (size_t)t, sizeof(uint32_t), (void **)&m->indices))
        return 0;
    for (size_t i = 0; i < 3 * (size_t)t; i++)
        if (m->indices[i] >= (uint32_t)v)
            return fail(w, SSG_WIRE_CORRUPT);
    return 1;
}

static int get_textures(struct ssg_wire *w, struct ssg_gltf *g)
{
    long long n, width, height, alpha;
    if (!get_int(w, 0, INT_MAX - 1, &n))
        return 0;
    if (!(g->textures = calloc((size_t)n + 1, sizeof *g->textures)))
        return fail(w, SSG_WIRE_NOMEM);
    for (; g->texture_count < n; g->texture_count++) {
        struct ssg_texture *t = &g->textures[g->texture_count];
        if (!get_int(w, 0, INT_MAX, &width) || !get_int(w, 0, INT_MAX, &height))
            return 0;
        t->width = (int)width, t->height = (int)height;
        if (!get_array(w, 3 * (size_t)width * (size_t)height, sizeof(float), (void **)&t->rgb) ||
            !get_int(w, 0, 1, &alpha) ||
            (alpha && !get_array(w, (size_t)width * (size_t)height, sizeof(float),
                                 (void **)&t->alpha)))
            return 0;
    }
    return 1;
}

/* Every material and mesh names a texture or material that came along. */
static int references_hold(struct ssg_wire *w, struct ssg_gltf *g)
{
    for (int i = 0; i < g->material_count; i++) {
        struct ssg_gltf_material *m = &g->materials[i];
        m->name[sizeof m->name - 1] = 0;
        m->texture_file[sizeof m->texture_file - 1] = 0;
        m->normal_file[sizeof m->normal_file - 1] = 0;
        if (m->texture < -1 || m->texture >= g->texture_count || m->alpha_mode < 0 ||
            m->normal_texture < -1 || m->normal_texture >= g->texture_count ||
            m->emission_texture < -1 || m->emission_texture >= g->texture_count ||
            !(m->emission[0] >= 0.0f && m->emission[1] >= 0.0f && m->emission[2] >= 0.0f &&
              isfinite(m->emission[0] + m->emission[1] + m->emission[2])) ||
            !isfinite(m->normal_scale) ||
            m->alpha_mode > SSG_ALPHA_BLEND || !(m->alpha_cutoff >= 0.0f) ||
            !(m->alpha_cutoff <= 1.0f))
            return fail(w, SSG_WIRE_CORRUPT);
    }
    for (int i = 0; i < g->mesh_count; i++)
        if (g->meshes[i].material >= g->material_count)
            return fail(w, SSG_WIRE_CORRUPT);
    return 1;
}

static int get_model(struct ssg_wire *w, struct ssg_gltf *g)
{
    long long meshes, materials, camera, lights;
    if (!get_int(w, 0, INT_MAX - 1, &meshes))
        return 0;
    if (!(g->meshes = calloc((size_t)meshes + 1, sizeof *g->meshes)))
        return fail(w, SSG_WIRE_NOMEM);
    while (g->mesh_count < meshes)
        if (!get_mesh(w, &g->meshes[g->mesh_count++]))
            return 0;
    if (!get_int(w, 0, INT_MAX, &materials) ||
        !get_array(w, (size_t)materials, sizeof *g->materials, (void **)&g->materials))
        return 0;
    g->material_count = (int)materials;
    if (!get_textures(w, g) || !get_int(w, 0, INT_MAX - 1, &lights) ||
        !get_array(w, (size_t)lights, sizeof *g->lights, (void **)&g->lights))
        return 0;
    g->light_count = (int)lights;
    for (int i = 0; i < g->light_count; i++)
        if (g->lights[i].kind != SSG_LIGHT_POINT && g->lights[i].kind != SSG_LIGHT_DIRECTIONAL &&
            g->lights[i].kind != SSG_LIGHT_SPOT)
            return fail(w, SSG_WIRE_CORRUPT);
    if (!get_int(w, 0, 1, &camera) ||
        !get(w, &g->camera, sizeof g->camera) || !get(w, g->ignored, sizeof g->ignored))
        return 0;
    g->ignored[sizeof g->ignored - 1] = 0;
    g->has_camera = (int)camera;
    return references_hold(w, g);
}

/* The code, the message and the up axis that lead every result. */
static int get_head(struct ssg_wire *w, long long *code, char *msg, size_t msg_len,
                    struct ssg_model_up *up)
{
    long long total, n;
    w->left = sizeof(int64_t);
    if (!get_int(w, 0, LLONG_MAX, &total))
        return 0;
    w->left = (unsigned long long)total;
    if (!get_int(w, 0, SSG_ERR_COUNT - 1, code) ||
        !get_int(w, 0, (long long)msg_len - 1, &n) || !get(w, msg, (size_t)n) ||
        !get(w, up, sizeof *up))
        return 0;
    msg[n] = 0;
    up->basis[sizeof up->basis - 1] = 0;
    return up->axis >= -1 && up->axis <= 2 && up->alt_axis >= 0 && up->alt_axis <= 2 &&
                   up->alt_sign >= -1 && up->alt_sign <= 1
               ? 1 : fail(w, SSG_WIRE_CORRUPT);
}

enum ssg_err ssg_wire_receive(struct ssg_wire *w, struct ssg_gltf **out,
                              struct ssg_model_up *up, char *why, size_t why_len)
{
    long long code = SSG_OK, has_model = 0;
    char msg[1024];
    struct ssg_gltf *g = NULL;
    if (out)
        *out = NULL;
    if (get_head(w, &code, msg, sizeof msg, up) && get_int(w, 0, 1, &has_model) && has_model) {
        if ((g = calloc(1, sizeof *g)) != NULL)
            get_model(w, g);
        else
            fail(w, SSG_WIRE_NOMEM);
    }
    if (w->left)
        fail(w, SSG_WIRE_CORRUPT);
    if (w->ending != SSG_WIRE_OK || !out)
        ssg_gltf_destroy(&g);
    if (w->ending != SSG_WIRE_OK)
        return SSG_E_GLTF;
    if (code)
        snprintf(why, why_len, "%s", msg);
    if (out)
        *out = g;
    return (enum ssg_err)code;
}
