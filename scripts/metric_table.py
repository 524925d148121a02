"""The metric table (testbed/harness/metric_table.h) as the testbed prints it, `testbed
metrics --json`: every script takes metric ids, headings, units, directions, references
and derived figures from here and names none of its own (tests/metric_names_test.py).

The binary: $TESTBED, else $TESTBED_BUILD_DIR/testbed/app/testbed, else
build/testbed/app/testbed beside scripts/ (as scripts/corpus.sh finds it). The testbed sets
$TESTBED for the scripts it runs itself.

Derived figures (frame_ms, memory_mb, invocations_k, ...) are computed once, in C++: a
record carries them in its "derived" block; `attach_derived` fills that block for records
written before it existed (`testbed metrics --derive FILE`), with the ratios to sm."""
import functools
import json
import os
import subprocess

REPOSITORY = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


class MetricTableError(Exception):
    """The table or the derived figures could not be had from the testbed (one line)."""


def testbed_binary():
    chosen = os.environ.get("TESTBED")
    if chosen:
        return chosen
    build = os.environ.get("TESTBED_BUILD_DIR") or os.path.join(REPOSITORY, "build")
    return os.path.join(build, "testbed", "app", "testbed")


def _run(arguments):
    binary = testbed_binary()
    try:
        result = subprocess.run([binary] + arguments, capture_output=True, text=True, check=False)
    except OSError as error:
        raise MetricTableError(f"{binary}: {error.strerror} (set $TESTBED to the testbed binary)") from error
    if result.returncode != 0:
        last = (result.stderr.strip().splitlines() or ["failed"])[-1]
        raise MetricTableError(f"{binary} {' '.join(arguments)}: {last}")
    return json.loads(result.stdout)


@functools.lru_cache(maxsize=None)
def _table():
    return tuple(_run(["metrics", "--json"]))


def metrics():
    """Every metric in table order: dicts with id, heading, brief, description, unit,
    digits, better ("lower"/"higher"), reference ("hard"/"soft"/"none"), path (a JSON
    pointer into a record, None for a ratio to sm), derived, from, shown_in, ..."""
    return list(_table())


def metric(name):
    for m in _table():
        if m["id"] == name:
            return m
    raise MetricTableError(f"no metric '{name}' in the testbed's metric table")


def ids():
    return [m["id"] for m in _table()]


def error_metrics():
    """The metrics measured against a reference (the hard ground truth or the area-light
    one), in table order: what statistics across scenes compare."""
    return [m for m in _table() if m["reference"] != "none"]


def lower_is_better(name):
    return metric(name)["better"] == "lower"


def _pointer(m):
    return m["path"] if m["path"] else "/derived/" + m["id"]


def value(record, name):
    """The finite number `record` holds for metric `name` (a derived figure from its
    "derived" block), or None."""
    node = record
    for key in _pointer(metric(name)).split("/")[1:]:
        if not isinstance(node, dict) or key not in node:
            return None
        node = node[key]
    if isinstance(node, bool) or not isinstance(node, (int, float)) or node != node or node in (float("inf"), float("-inf")):
        return None
    return node


def path_keys(name):
    """The keys that lead to metric `name` in a record: ("error", "boundary_px", "mean")."""
    return tuple(_pointer(metric(name)).split("/")[1:])


def attach_derived(file, records):
    """Sets every record's "derived" block from `testbed metrics --derive FILE` (records
    is FILE's array as read), so older records read like new ones and ratios to sm are
    there too."""
    derived = _run(["metrics", "--derive", file])
    if len(derived) != len(records):
        raise MetricTableError(f"{file}: the testbed derived {len(derived)} records of {len(records)}")
    for record, block in zip(records, derived):
        record["derived"] = block
    return records
