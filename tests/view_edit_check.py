#!/usr/bin/python3
"""view_edit_check.py - is a graph file that `ssgraph view` saved the graph its page shows?
`ssgraph check FILE` must pass, and `ssgraph dot FILE` must have the nodes of the page's
/api/state (name and type) and its connections (producer's node.port into the reader's
input). Used by test_view_edit_http.sh (as a program: BIN FILE STATE.json, exit status 1
with the differences printed) and view_edit.py (problems())."""
import json
import re
import subprocess
import sys


def graph_of_dot(dot):
    """({name: type}, {(from_node, from_port, to_node, to_input)}) of `ssgraph dot`."""
    nodes = dict(re.findall(r'^\s*"([^"]+)" \[label="[^\\"]*\\n\(([^)]*)\)"\];', dot, re.M))
    edges = {(a, p, b, q) for a, b, p, q in
             re.findall(r'^\s*"([^"]+)" -> "([^"]+)" \[label="(\S+) -> (\S+)"\];', dot, re.M)}
    return nodes, edges


def graph_of_state(state):
    nodes = {n["name"]: n["type"] for n in state["nodes"]}
    edges = {(*i["from"].split("."), n["name"], i["port"]) for n in state["nodes"]
             for i in n["inputs"] if i["from"]}
    return nodes, edges


def problems(binary, path, state):
    """What differs between the saved file and the state, as lines ([] = the same)."""
    check = subprocess.run([binary, "check", path], capture_output=True, text=True)
    if check.returncode != 0:
        return [f"ssgraph check {path}: {check.stdout}{check.stderr}"]
    dot = subprocess.run([binary, "dot", path], capture_output=True, text=True)
    if dot.returncode != 0:
        return [f"ssgraph dot {path}: {dot.stderr}"]
    (fn, fe), (pn, pe) = graph_of_dot(dot.stdout), graph_of_state(state)
    out = []
    if fn != pn:
        out.append(f"nodes: the file has {sorted(fn.items())}, the page {sorted(pn.items())}")
    if fe != pe:
        out.append(f"connections only in the file: {sorted(fe - pe)}; only in the page: "
                   f"{sorted(pe - fe)}")
    return out


if __name__ == "__main__":
    with open(sys.argv[3]) as f:
        found = problems(sys.argv[1], sys.argv[2], json.load(f))
    for line in found:
        print(line)
    sys.exit(1 if found else 0)
