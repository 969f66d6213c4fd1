/* api_describe.c - descriptors through the public interface (ssgraph_tools.h, "Descriptors
 * of parameters and ports"): what a generated user interface (ssgraph view's parameter
 * panel, a Python binding) needs to draw a control for each parameter and list each port,
 * read from the same tables that parse and check graph files. Reads only. */
#include <stdio.h>
#include <string.h>

#include "graph/graph.h"
#include "lang/params.h"

enum ssg_err ssg_node_param_info(const char *node, int k, struct ssg_param_info *info)
{
    *info = (struct ssg_param_info){0};
    const struct ssg_node_desc *desc = node ? ssg_node_find(node, strlen(node)) : NULL;
    if (!desc)
        return SSG_E_UNKNOWN_NODE;
    if (k < 0 || k >= desc->params.count)
        return SSG_E_USAGE;
    const struct ssg_param_desc *p = &desc->params.params[k];
    int soft = ssg_param_has_soft(p);
    *info = (struct ssg_param_info){
        .name = p->name, .type = ssg_param_type_name(p), .unit = p->unit, .doc = p->help,
        .bounded = !(p->min == 0 && p->max == 0), .min = p->min, .max = p->max,
        .choices = p->type == SSG_P_ENUM ? p->choices : NULL,
        .soft_min = soft ? p->soft_min : p->min, .soft_max = soft ? p->soft_max : p->max};
    return SSG_OK;
}

/* The name of a one-type mask ("scalar"); "" for none or several. */
static const char *type_name(unsigned mask)
{
    return mask && !(mask & (mask - 1)) ? ssg_type_name(__builtin_ctz(mask)) : "";
}

/* The input k of node n (its ports, then its extra named inputs). */
static void input_info(const struct gnode *n, int k, struct ssg_port_info *info)
{
    const struct gconn *c;
    if (k < n->desc->input_count) {
        const struct ssg_port_desc *d = &n->desc->inputs[k];
        c = &n->in[k];
        info->name = d->name;
        info->doc = d->doc;
        info->optional = d->optional;
    } else {
        k -= n->desc->input_count;
        c = &n->extra[k];
        info->name = n->extra_names[k];
        info->doc = "";
    }
    if (c->ref)
        snprintf(info->from, sizeof info->from, "%s", c->ref);
}

int ssg_graph_port_count(const struct ssg_graph *g, int index)
{
    if (index < 0 || index >= g->count || !g->nodes[index].desc)
        return 0;
    const struct gnode *n = &g->nodes[index];
    return n->desc->input_count + n->extra_count + n->desc->output_count;
}

enum ssg_err ssg_graph_port_inspect(const struct ssg_graph *g, int index, int k,
                                    struct ssg_port_info *info)
{
    *info = (struct ssg_port_info){0};
    if (k < 0 || k >= ssg_graph_port_count(g, index))
        return SSG_E_USAGE;
    const struct gnode *n = &g->nodes[index];
    int inputs = n->desc->input_count + n->extra_count;
    if (k < inputs) {
        input_info(n, k, info);
        const struct ssg_shape *s = k < n->desc->input_count ? &n->in_shape[k] : NULL;
        info->type = type_name(s ? s->type : 0);
        info->channels = s ? s->channels : 0;
        return SSG_OK;
    }
    k -= inputs;
    const struct ssg_port_desc *d = &n->desc->outputs[k];
    const struct ssg_shape *s = &n->out_shape[k];
    /* A loaded graph knows the shape (same_as outputs take their input's); a parsed one
       only the declared type. */
    unsigned type = s->type ? s->type : d->types;
    info->name = d->name;
    info->doc = d->doc;
    info->output = 1;
    info->type = type_name(type);
    info->channels = s->channels ? s->channels : ssg_type_channels(type);
    info->width = s->width;
    info->height = s->height;
    info->has_image = ssg_graph_output_kept(g, index, k);
    return SSG_OK;
}

int ssg_node_port_count(const char *node)
{
    const struct ssg_node_desc *d = node ? ssg_node_find(node, strlen(node)) : NULL;
    return d ? d->input_count + d->output_count : 0;
}

enum ssg_err ssg_node_port_info(const char *node, int k, struct ssg_type_port *info)
{
    if (!info)
        return SSG_E_USAGE;
    *info = (struct ssg_type_port){0};
    const struct ssg_node_desc *d = node ? ssg_node_find(node, strlen(node)) : NULL;
    if (!d)
        return SSG_E_UNKNOWN_NODE;
    if (k < 0 || k >= d->input_count + d->output_count)
        return SSG_E_USAGE;
    int output = k >= d->input_count;
    const struct ssg_port_desc *p = output ? &d->outputs[k - d->input_count] : &d->inputs[k];
    info->name = p->name;
    info->doc = p->doc;
    info->output = output;
    info->optional = !output && p->optional;
    unsigned types = p->types;
    int from = output && p->same_as ? ssg_port_find(d->inputs, d->input_count, p->same_as,
                                                    strlen(p->same_as)) : -1;
    if (from >= 0) /* shaped like that input: it makes what it is given */
        types = d->inputs[from].types;
    ssg_type_names(types, info->types, sizeof info->types);
    return SSG_OK;
}
