/* bench_json_adapter.cc - bench.json into C structs (bench_json.h) with nlohmann::json,
 * whose ordered_json keeps the metrics and nodes in the order the file lists them (the
 * order the tables are written in). Every exception stays in this file. */
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>

#include <nlohmann/json.hpp>

extern "C" {
#include "bench_json.h"
}

using nlohmann::ordered_json;

namespace {

struct bad_file {
    std::string what;
};

const ordered_json &field(const ordered_json &obj, const char *key)
{
    if (!obj.is_object() || !obj.contains(key))
        throw bad_file{std::string("no \"") + key + "\""};
    return obj.at(key);
}

void copy_text(const ordered_json &obj, const char *key, char *out, size_t len)
{
    const ordered_json &v = field(obj, key);
    if (!v.is_string())
        throw bad_file{std::string("\"") + key + "\" is not a string"};
    std::string s = v.get<std::string>();
    if (s.size() >= len)
        throw bad_file{std::string("\"") + key + "\" is too long"};
    std::memcpy(out, s.c_str(), s.size() + 1);
}

int integer(const ordered_json &obj, const char *key, long lo, long hi)
{
    const ordered_json &v = field(obj, key);
    if (!v.is_number_integer() || v.get<long>() < lo || v.get<long>() > hi)
        throw bad_file{std::string("\"") + key + "\" is not an integer in range"};
    return (int)v.get<long>();
}

double number(const ordered_json &obj, const char *key)
{
    const ordered_json &v = field(obj, key);
    if (!v.is_number())
        throw bad_file{std::string("\"") + key + "\" is not a number"};
    return v.get<double>();
}

/* A number a bench.json of an older ssgraph lacks: `fallback` then. */
double number_or(const ordered_json &obj, const char *key, double fallback)
{
    return obj.contains(key) ? number(obj, key) : fallback;
}

/* A metric: a number, or "inf", "-inf", "nan" (JSON has no infinity). */
double metric_value(const ordered_json &v)
{
    if (v.is_number())
        return v.get<double>();
    if (v.is_string() && v == "inf")
        return std::numeric_limits<double>::infinity();
    if (v.is_string() && v == "-inf")
        return -std::numeric_limits<double>::infinity();
    if (v.is_string() && v == "nan")
        return std::numeric_limits<double>::quiet_NaN();
    throw bad_file{"a metric is not a number"};
}

void read_sweeps(const ordered_json &doc, ssg_bench_json *out)
{
    const ordered_json &sweeps = field(doc, "sweeps");
    if (!sweeps.is_array() || sweeps.size() > SSG_BENCH_MAX_SWEEPS)
        throw bad_file{"\"sweeps\" is not a list of at most 4"};
    out->sweep_count = (int)sweeps.size();
    for (int k = 0; k < out->sweep_count; k++) {
        copy_text(sweeps[k], "key", out->sweep_keys[k], sizeof out->sweep_keys[k]);
        const ordered_json &values = field(sweeps[k], "values");
        if (!values.is_array() || values.empty() || values.size() > 64)
            throw bad_file{"a sweep's \"values\" is not a list of 1 to 64"};
        out->value_count[k] = (int)values.size();
        for (size_t v = 0; v < values.size(); v++) {
            if (!values[v].is_string() || values[v].get<std::string>().size() >= 256)
                throw bad_file{"a sweep value is not a short string"};
            std::strcpy(out->values[k][v], values[v].get<std::string>().c_str());
        }
    }
}

void read_stats(const ordered_json &c, ssg_run_stats *st)
{
    st->frames = integer(c, "frames", 0, 1000000);
    st->frame_avg_ms = number(c, "frame_avg_ms");
    st->frame_min_ms = number(c, "frame_min_ms");
    st->frame_max_ms = number(c, "frame_max_ms");
    st->frame_median_ms = number_or(c, "frame_median_ms", st->frame_avg_ms);
    const ordered_json &metrics = field(c, "metrics"), &nodes = field(c, "node_ms");
    if (!metrics.is_object() || !nodes.is_object())
        throw bad_file{"a cell's \"metrics\" or \"node_ms\" is not an object"};
    st->metrics = (ssg_run_metric *)calloc(metrics.size() + 1, sizeof *st->metrics);
    st->nodes = (ssg_run_node *)calloc(nodes.size() + 1, sizeof *st->nodes);
    if (!st->metrics || !st->nodes)
        throw std::bad_alloc();
    for (auto &m : metrics.items()) {
        ssg_run_metric *out = &st->metrics[st->metric_count];
        size_t dot = m.key().find('.');
        if (dot == std::string::npos || dot >= sizeof out->node ||
            m.key().size() - dot - 1 >= sizeof out->name)
            throw bad_file{"a metric is not named node.metric"};
        std::snprintf(out->node, sizeof out->node, "%.*s", (int)dot, m.key().c_str());
        std::snprintf(out->name, sizeof out->name, "%s", m.key().c_str() + dot + 1);
        out->value = metric_value(m.value());
        st->metric_count++;
    }
    for (auto &n : nodes.items()) {
        if (!n.value().is_number())
            throw bad_file{"a node's ms is not a number"};
        ssg_run_node *out = &st->nodes[st->node_count];
        out->name = strdup(n.key().c_str());
        if (!out->name)
            throw std::bad_alloc();
        st->node_count++;
        out->avg_ms = n.value().get<double>();
        out->type = "";
        out->backend = "";
    }
}

/* Each node's median, fastest and slowest run, listed by name as node_ms lists its average;
   a bench.json of an older ssgraph has only the average, which then stands for each. */
void read_node_times(const ordered_json &c, ssg_run_stats *st)
{
    static const struct {
        const char *key;
        double ssg_run_node::*field;
    } times[] = {{"node_median_ms", &ssg_run_node::median_ms},
                 {"node_min_ms", &ssg_run_node::min_ms},
                 {"node_max_ms", &ssg_run_node::max_ms}};
    for (const auto &t : times) {
        for (int i = 0; i < st->node_count; i++)
            st->nodes[i].*t.field = st->nodes[i].avg_ms;
        if (!c.contains(t.key))
            continue;
        const ordered_json &obj = c.at(t.key);
        if (!obj.is_object())
            throw bad_file{std::string("a cell's \"") + t.key + "\" is not an object"};
        for (int i = 0; i < st->node_count; i++) {
            auto it = obj.find(st->nodes[i].name);
            if (it == obj.end() || !it->is_number())
                throw bad_file{std::string("a cell's \"") + t.key + "\" lacks a node of node_ms"};
            st->nodes[i].*t.field = it->get<double>();
        }
    }
}

void read_cells(const ordered_json &doc, ssg_bench_json *out)
{
    const ordered_json &cells = field(doc, "cells");
    if (!cells.is_array() || cells.size() > (size_t)out->cells_total)
        throw bad_file{"\"cells\" is not a list of at most cells_total"};
    out->cells = (ssg_bench_json_cell *)calloc(cells.size() + 1, sizeof *out->cells);
    if (!out->cells)
        throw std::bad_alloc();
    for (const ordered_json &c : cells) {
        ssg_bench_json_cell *cell = &out->cells[out->cell_count++];
        cell->index = integer(c, "cell", 0, out->cells_total - 1);
        const ordered_json &status = field(c, "status");
        if (status != "ok" && status != "error")
            throw bad_file{"a cell's \"status\" is neither ok nor error"};
        cell->ok = status == "ok";
        copy_text(c, "error", cell->error, sizeof cell->error);
        read_stats(c, &cell->stats);
        read_node_times(c, &cell->stats);
    }
}

void read_all(const char *text, size_t len, ssg_bench_json *out)
{
    ordered_json doc = ordered_json::parse(text, text + len);
    copy_text(doc, "graph", out->graph, sizeof out->graph);
    copy_text(doc, "time_node", out->time_node, sizeof out->time_node);
    copy_text(doc, "error_metric", out->error_metric, sizeof out->error_metric);
    copy_text(doc, "reference", out->reference, sizeof out->reference);
    copy_text(doc, "definition", out->definition, sizeof out->definition);
    copy_text(doc, "definition_hash", out->definition_hash, sizeof out->definition_hash);
    const ordered_json &shard = field(doc, "shard");
    out->shard_count = integer(shard, "count", 1, 100000);
    out->shard_index = integer(shard, "index", 0, out->shard_count - 1);
    out->cells_total = integer(doc, "cells_total", 1, 10000);
    read_sweeps(doc, out);
    read_cells(doc, out);
}

} // namespace

extern "C" int ssg_bench_json_parse(const char *text, size_t len, struct ssg_bench_json *out,
                                    char *why, size_t why_len)
{
    std::memset(out, 0, sizeof *out);
    try {
        read_all(text, len, out);
        return 0;
    } catch (const bad_file &e) {
        std::snprintf(why, why_len, "not a bench.json of ssgraph bench: %s", e.what.c_str());
    } catch (const nlohmann::json::exception &e) {
        std::snprintf(why, why_len, "not JSON: %s", e.what());
    } catch (const std::exception &e) {
        std::snprintf(why, why_len, "%s", e.what());
    }
    ssg_bench_json_free(out);
    return 1;
}

extern "C" void ssg_bench_json_free(struct ssg_bench_json *j)
{
    for (int i = 0; j->cells && i < j->cell_count; i++)
        ssg_run_stats_free(&j->cells[i].stats);
    std::free(j->cells);
    j->cells = nullptr;
    j->cell_count = 0;
}
