"""accuracy_values.py - the values test_accuracy.sh and test_accuracy_gi.sh check: each row's
RMSE and FLIP in the tables of `bench.py --accuracy` against tests/fixtures/accuracy_expected.tsv.

  check PART TABLE.md EXPECTED.tsv   PART's rows (ao or gi) against EXPECTED's, within the
                                     tolerances there; prints how far they are; exit 1 with
                                     each row or total that is out of bounds
  write PART TABLE.md EXPECTED.tsv   replaces PART's rows of EXPECTED by TABLE's (comments,
                                     bounds and the other part's rows are kept)

A row's key is its text columns: (scene, method) in the AO table, (light, scene, method) in the
GI per-scene table; the GI summary rows are means of those and are not read. Four bounds a
metric, each on got - expected: `row` on every row; `group_rms` and `group_mean` on the root
mean square and the mean over each method's rows (AO: a method; GI: a light and a method, the
scenes' rows); `mean` on the mean over every row. A changed default or metric moves many rows
of its methods the same way: their mean shows it long before one row leaves the seeds' spread,
and a mean over one method is not diluted by the methods it does not touch."""
import math
import re
import sys

# The AO table's rows: | scene | method | rmse | flip | bias | ssim | ms |
AO_ROW = re.compile(r"^\| ([a-z_]+) \| ((?:ssao|hbao|gtao)(?: \+ bilateral)?) \| ([0-9.]+) \| "
                    r"([0-9.]+) \| [+-][0-9.]+ \| -?[0-9.]+ \| (?:[0-9.]+|-) \|$")
# The GI per-scene rows:
# | light | scene | method | rmse | flip | structure_pp | bias | ssim | bounce |
GI_ROW = re.compile(r"^\| (own|sun|sky|courtyard) \| ([a-z_]+) \| "
                    r"(none|ssao|ssdo|hybrid|hybrid_ssdo|gi) \| ([0-9.]+) \| ([0-9.]+) \| "
                    r"(?:[0-9.]+|-) \| [+-][0-9.]+ \| -?[0-9.]+ \| (?:[0-9.]+|-) \|$")
METRICS = ("rmse", "flip")
BOUNDS = ("row", "group_rms", "group_mean", "mean")


def table_rows(part, path):
    """{key tuple: (rmse, flip)} of PART's rows in a bench.py --accuracy table."""
    pattern, keys = (AO_ROW, 2) if part == "ao" else (GI_ROW, 3)
    rows = {}
    with open(path) as f:
        for line in f:
            m = pattern.match(line.rstrip("\n"))
            if m:
                g = m.groups()
                rows[g[:keys]] = (float(g[keys]), float(g[keys + 1]))
    return rows


def expected(part, path):
    """PART's ({key tuple: (rmse, flip)}, {(bound, metric): tolerance}) in the expectations
    file: tab-separated lines `PART key... rmse flip` and `tolerance PART bound rmse flip`;
    # starts a comment."""
    rows, tol = {}, {}
    with open(path) as f:
        for line in f:
            cols = line.rstrip("\n").split("\t")
            if line.startswith("#") or len(cols) < 4:
                continue
            if cols[0] == "tolerance" and cols[1] == part:
                for name, v in zip(METRICS, cols[3:5]):
                    tol[cols[2], name] = float(v)
            elif cols[0] == part:
                rows[tuple(cols[1:-2])] = (float(cols[-2]), float(cols[-1]))
    return rows, tol


def group_of(key):
    """A row's method: (method,) in the AO table, (light, method) in the GI table."""
    return (key[0], key[-1]) if len(key) == 3 else key[-1:]


def check_metric(part, i, name, keys, got, want, tol):
    """The bounds of one metric; each broken one as a message."""
    d = {k: got[k][i] - want[k][i] for k in keys}
    errors = [f"{' | '.join(k)}: {name} {got[k][i]} expected {want[k][i]} +- "
              f"{tol['row', name]}" for k in keys if abs(d[k]) > tol["row", name]]
    groups = {}
    for k in keys:
        groups.setdefault(group_of(k), []).append(d[k])
    worst_rms = worst_mean = 0.0
    for g, v in sorted(groups.items()):
        rms, mean = math.sqrt(sum(x * x for x in v) / len(v)), sum(v) / len(v)
        worst_rms, worst_mean = max(worst_rms, rms), max(worst_mean, abs(mean))
        if rms > tol["group_rms", name] or abs(mean) > tol["group_mean", name]:
            errors.append(f"{part} {' | '.join(g)}: {name} differences over its {len(v)} rows: "
                          f"rms {rms:.4f} (bound {tol['group_rms', name]}), mean {mean:+.4f} "
                          f"(bound {tol['group_mean', name]})")
    mean = sum(d.values()) / len(d)
    if abs(mean) > tol["mean", name]:
        errors.append(f"{part} {name}: mean difference {mean:+.4f}, bound {tol['mean', name]}")
    print(f"{part} {name}: {len(d)} rows, max |d| {max(map(abs, d.values())):.4f} (bound "
          f"{tol['row', name]}); {len(groups)} methods, worst rms {worst_rms:.4f} "
          f"({tol['group_rms', name]}), worst |mean| {worst_mean:.4f} "
          f"({tol['group_mean', name]}); mean {mean:+.4f} ({tol['mean', name]})")
    return errors


def check(part, table, path):
    """Every expected row present, no row unexpected, the differences within the bounds."""
    got = table_rows(part, table)
    want, tol = expected(part, path)
    if not want or len(tol) != len(BOUNDS) * len(METRICS):
        return [f"{path}: no {part} rows or not every bound of {part}"]
    errors = [f"missing row {' | '.join(k)}" for k in want if k not in got]
    errors += [f"unexpected row {' | '.join(k)} (not in {path})" for k in got if k not in want]
    keys = sorted(want.keys() & got.keys())
    for i, name in enumerate(METRICS):
        errors += check_metric(part, i, name, keys, got, want, tol)
    return errors


def write(part, table, path):
    """Rewrites the expectations file with PART's rows taken from TABLE: comments and bounds
    first, as they were, then the rows, ao before gi, each part sorted."""
    with open(path) as f:
        lines = f.readlines()
    head = [line for line in lines if line.startswith("#") or line.startswith("tolerance\t")]
    rows = [line for line in lines if line.split("\t")[0] in ("ao", "gi") and
            line.split("\t")[0] != part]
    new = table_rows(part, table)
    if not new:
        sys.exit(f"accuracy_values: {table} has no {part} rows")
    rows += ["\t".join((part,) + key + tuple(f"{v:g}" for v in val)) + "\n"
             for key, val in sorted(new.items())]
    rows.sort(key=lambda line: line.split("\t")[0])  # stable: each part keeps its order
    with open(path, "w") as f:
        f.writelines(head + rows)


def main(argv):
    if len(argv) != 4 or argv[0] not in ("check", "write") or argv[1] not in ("ao", "gi"):
        sys.exit(__doc__)
    if argv[0] == "write":
        write(*argv[1:])
        return 0
    errors = check(*argv[1:])
    for e in errors[:40]:
        print(e)
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
