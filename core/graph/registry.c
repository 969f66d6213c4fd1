/* registry.c - the node registry, built from the one list in nodes/nodes.def, and the
 * descriptions (`ssgraph nodes`, `ssgraph describe`) printed from each node's descriptor
 * table; docs/nodes.md is node_docs.c. */
#include <stdio.h>
#include <string.h>

#include "graph/node.h"

#define X(name) extern const struct ssg_node_desc ssg_node_##name;
#include "nodes.def"
#undef X

static const struct ssg_node_desc *const registry[] = {
#define X(name) &ssg_node_##name,
#include "nodes.def"
#undef X
};

enum { REGISTRY_COUNT = sizeof registry / sizeof registry[0] };
_Static_assert(REGISTRY_COUNT <= 64, "node_docs.c keeps the node types a graph uses in 64 bits");

int ssg_node_count(void)
{
    return REGISTRY_COUNT;
}

const char *ssg_node_name(int index)
{
    return index >= 0 && index < REGISTRY_COUNT ? registry[index]->name : NULL;
}

const char *ssg_node_summary(int index)
{
    return index >= 0 && index < REGISTRY_COUNT ? registry[index]->summary : NULL;
}

const struct ssg_node_desc *ssg_node_find(const char *name, size_t len)
{
    for (int i = 0; i < REGISTRY_COUNT; i++)
        if (ssg_tok_eq(name, len, registry[i]->name))
            return registry[i];
    return NULL;
}

int ssg_port_find(const struct ssg_port_desc *ports, int count, const char *name, size_t len)
{
    for (int i = 0; i < count; i++)
        if (ssg_tok_eq(name, len, ports[i].name))
            return i;
    return -1;
}

/* The port types' names and what each holds, in the bit order of enum ssg_type: the
   messages, `describe` and the glossary of docs/nodes.md all read them from here. */
static const struct {
    const char *name, *doc;
} port_types[] = {
    {"scalar", "1 channel, frame-sized: depth, occlusion, modulation"},
    {"vector", "3 channels, frame-sized: view-space position or normal (x, y, z)"},
    {"color", "3 channels, frame-sized: linear RGB radiance, irradiance or albedo"},
    {"kernel", "count x 1, 3 channels: sample offsets in the unit hemisphere around +z "
               "(tangent space), of length at most 1 (halton, and what ssao, ssdo and hbao sample with)"},
    {"pattern", "n x n tile, 2 channels: a per-pixel rotation (cos, sin) of the kernel, "
                "tiled over the frame; or 4 channels: and a per-pixel shift of the sample "
                "lengths, offset and index shift (ssao, ssdo and bounce read them)"},
    {"lights", "count x 2, 3 channels: directional lights; row 0 the unit world direction "
               "towards light i, row 1 its RGB irradiance on a surface facing it"},
    {"shadowmaps", "R x R, one channel per light of a lights list: the depth of the nearest "
                   "surface below each texel of light i's orthographic map"},
    {"lightmaps", "R x R, a stack of faces of the maps of the scene's own point, spot and "
                  "directional lights (a cube of 6 faces a point light or a spot wider "
                  "than 60 degrees, 1 a directional light or a narrower spot): depth, "
                  "normal or reflected flux of the nearest surface per texel"},
};

const char *ssg_type_name(int bit)
{
    return bit >= 0 && bit < SSG_COUNT(port_types) ? port_types[bit].name : NULL;
}

const char *ssg_type_doc(int bit)
{
    return bit >= 0 && bit < SSG_COUNT(port_types) ? port_types[bit].doc : NULL;
}

const struct ssg_node_desc *ssg_node_at(int index)
{
    return index >= 0 && index < REGISTRY_COUNT ? registry[index] : NULL;
}

void ssg_type_names(unsigned mask, char *buf, size_t len)
{
    size_t n = 0;
    buf[0] = 0;
    for (int i = 0; i < SSG_COUNT(port_types) && n < len; i++)
        if (mask & (1u << i))
            n += (size_t)snprintf(buf + n, len - n, "%s%s", n ? "|" : "", port_types[i].name);
}

int ssg_type_channels(unsigned type)
{
    if (type & SSG_T_SCALAR)
        return 1;
    if (type & (SSG_T_VECTOR | SSG_T_COLOR))
        return 3;
    return 0;
}

static void describe_ports(const char *title, const struct ssg_port_desc *ports, int count,
                           int is_input, FILE *stream)
{
    fprintf(stream, "%s:\n", title);
    if (count == 0)
        fprintf(stream, "  (none)\n");
    for (int i = 0; i < count; i++) {
        char types[64];
        ssg_type_names(ports[i].types, types, sizeof types);
        if (ports[i].same_as)
            snprintf(types, sizeof types, "same as %s", ports[i].same_as);
        fprintf(stream, "  %-16s %-22s %s%s\n", ports[i].name, types, ports[i].doc,
                is_input && ports[i].optional     ? " (optional)"
                : !is_input && ports[i].on_demand ? " (computed only when read)"
                                                  : "");
    }
}

const char *ssg_node_readme(const char *node)
{
    for (const struct ssg_node_readme *r = ssg_node_readmes; r->node; r++)
        if (!strcmp(r->node, node))
            return r->text;
    return NULL;
}

const char *ssg_node_doc(const struct ssg_node_desc *d, int *len)
{
    const char *text = ssg_node_readme(d->name);
    if (!text)
        text = d->doc ? d->doc : "";
    else if (text[0] == '#') { /* the title: `ssgraph describe` and docs/nodes.md have theirs */
        const char *nl = strchr(text, '\n');
        text = nl ? nl + 1 : "";
    }
    while (*text == '\n')
        text++;
    size_t n = strlen(text);
    while (n && text[n - 1] == '\n')
        n--;
    *len = (int)n;
    return text;
}

const char *ssg_node_backends(const struct ssg_node_desc *d)
{
    return d->run_gl ? "cpu, gl" : "cpu only";
}

enum ssg_err ssg_node_describe(const char *node, FILE *stream)
{
    if (!node || !stream)
        return SSG_E_USAGE;
    const struct ssg_node_desc *d = ssg_node_find(node, strlen(node));
    if (!d)
        return SSG_E_UNKNOWN_NODE;
    int doc_len;
    const char *doc = ssg_node_doc(d, &doc_len);
    fprintf(stream, "%s - %s\n\n%.*s\n\nMethod: %s\n\nBackends: %s (backend=cpu|gl on the "
            "node, `backend` in the graph, --backend)\n\n", d->name, d->summary,
            doc_len, doc, d->method, ssg_node_backends(d));
    describe_ports("Inputs", d->inputs, d->input_count, 1, stream);
    if (d->extra_inputs)
        fprintf(stream, "  %-16s %-22s %s\n", "<name>=node.port", "any image",
                "further inputs, written as named layers");
    describe_ports("Outputs", d->outputs, d->output_count, 0, stream);
    fprintf(stream, "Parameters:\n");
    if (d->params.count == 0)
        fprintf(stream, "  (none)\n");
    for (int i = 0; i < d->params.count; i++)
        ssg_param_describe(&d->params.params[i], stream);
    return SSG_OK;
}
