/* test_gl_binding.c - binding by the tables on the GL backend (core/gl/gl.h): a name the
 * shader lacks is an error naming node, shader and uniform, never a silent skip; a
 * parameter or constant its tables declare for the shader (#pragma ssg_params,
 * ssg_consts) that the shader never reads is an error naming it; a pass without the
 * node's parameters is refused; and the real ssao shader binds every row of its tables
 * without naming one. */
#include <string.h>

#include "check.h"
#include "gl/gl.h"
#include "graph/gl_backend.h"
#include "ssao/ssao.h"

extern const struct ssg_node_desc ssg_node_ssao;

static int has_diag(const struct ssg_diags *d, const char *a, const char *b, const char *c)
{
    for (int i = 0; i < d->count; i++)
        if (d->items[i].code == SSG_E_SHADER && strstr(d->items[i].message, a) &&
            strstr(d->items[i].message, b) && strstr(d->items[i].message, c))
            return 1;
    return 0;
}

static struct ssg_frame frame = {.width = 8, .height = 8, .fov_y = 60};
static struct ssg_ssao_consts consts; /* the values do not matter here, only the names */

static struct ssg_node_ctx ctx_of(const struct ssg_node_desc *desc, const void *params,
                                  struct ssg_diags *d)
{
    return (struct ssg_node_ctx){.desc = desc, .instance = "ao", .frame = &frame, .diags = d,
                                 .params = params, .consts = &consts};
}

/* The parameters bind by themselves; a misspelled uniform then fails the pass. */
static void misspelled_uniform_is_an_error(void)
{
    struct ssg_ssao_params params;
    ssg_params_defaults(ssg_node_ssao.params, &params);
    struct ssg_diags d = {0};
    struct ssg_node_ctx ctx = ctx_of(&ssg_node_ssao, &params, &d);
    struct ssg_gl_pass p;
    CHECK_EQ(ssg_gl_pass_begin(&p, &ctx, "ssao.glsl", NULL), SSG_OK);
    ssg_gl_float(&p, "inv_samples", 0.25f); /* the shader's own name: fine */
    CHECK_EQ(p.err, SSG_OK);
    ssg_gl_float(&p, "inv_sampels", 0.25f);
    CHECK_EQ(ssg_gl_pass_end(&p), SSG_E_SHADER);
    ssg_diags_print(&d, stderr);
    CHECK(has_diag(&d, "ssao 'ao'", "ssao.glsl", "'inv_sampels'"));
}

/* A row the shader does not read: the table declares it, the compiler drops it. `which`
   0 adds a parameter row (p_<name>), 1 a constant's row (<name>). */
static void unread_row_is_an_error(int which, const char *name, const char *expect)
{
    static struct ssg_param_desc rows[2][16]; /* static: the program cache keys by the node */
    static struct ssg_node_desc descs[2];
    struct ssg_node_desc *desc = &descs[which];
    *desc = ssg_node_ssao;
    struct ssg_param_table *table = which ? &desc->uniforms : &desc->params;
    int n = table->count;
    CHECK(n > 0 && n < 16);
    memcpy(rows[which], table->params, (size_t)n * sizeof rows[0][0]);
    rows[which][n] = (struct ssg_param_desc){.name = name, .type = SSG_P_FLOAT};
    *table = (struct ssg_param_table){rows[which], n + 1};
    struct ssg_ssao_params params;
    ssg_params_defaults(ssg_node_ssao.params, &params);
    struct ssg_diags d = {0};
    struct ssg_node_ctx ctx = ctx_of(desc, &params, &d);
    struct ssg_gl_pass p;
    CHECK_EQ(ssg_gl_pass_begin(&p, &ctx, "ssao.glsl", NULL), SSG_E_SHADER);
    ssg_diags_print(&d, stderr);
    CHECK(has_diag(&d, "ssao 'ao'", name, expect));
}

static void pass_without_parameters_is_refused(void)
{
    struct ssg_diags d = {0};
    struct ssg_node_ctx ctx = ctx_of(&ssg_node_ssao, NULL, &d);
    struct ssg_gl_pass p;
    CHECK(ssg_gl_pass_begin(&p, &ctx, "ssao.glsl", NULL) != SSG_OK);
    CHECK(d.count == 1 && strstr(d.items[0].message, "ctx->params"));
}

int main(void)
{
    struct ssg_diags d = {0};
    if (ssg_gl_open(&d) != SSG_OK) {
        ssg_diags_print(&d, stderr);
        return 1;
    }
    misspelled_uniform_is_an_error();
    unread_row_is_an_error(0, "unread_knob", "read it as p_unread_knob");
    unread_row_is_an_error(1, "unread_const", "constant 'unread_const' (#pragma ssg_consts)");
    pass_without_parameters_is_refused();
    ssg_gl_close();
    return check_report();
}
