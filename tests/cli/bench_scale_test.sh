#!/usr/bin/env bash
# bench scale measures 1 rank in-process and 2 ranks through mpirun (when MPI is built in),
# splits the time into compute and communication, and feeds the cluster model.
set -euo pipefail
hexgait="$1"
out="$(mktemp)"
trap 'rm -f "$out"' EXIT
"$hexgait" bench scale --ranks 1,2 --population 12 --generations 2 --time 5 \
  --model-ranks 16,64 --model-evaluations 20000000 --json >"$out"
mpi=0
if "$hexgait" --version | grep -q "MPI built in" && command -v mpirun >/dev/null; then mpi=1; fi
python3 - "$out" "$mpi" <<'PY'
import json, sys
j = json.load(open(sys.argv[1]))
mpi = sys.argv[2] == "1"
rows = {r["ranks"]: r for r in j["measured"]}
assert set(rows) == ({1, 2} if mpi else {1}), rows.keys()
for r in rows.values():
    assert r["evaluations_per_second"] > 0, r
    assert 0 < r["seconds_compute"] <= r["seconds_generation"], r
    assert r["seconds_communication"] >= 0, r
assert rows[1]["bytes_per_generation"] == 0
if mpi:
    # 6 of 12 tables go to rank 1 and 6 results come back: at least the tables' doubles.
    assert rows[2]["bytes_per_generation"] > 6 * 8 * 40, rows[2]
    assert j["mpi"] is True
m = j["model"]
assert m["seconds_per_eval_core"] > 0 and m["bytes_per_eval"] > 0 and m["lanes"] >= 1, m
assert len(j["predicted"]) == 12
assert sorted({p["ranks"] for p in j["predicted"]}) == [16, 64]
assert m["evaluations"] == 20000000
for p in j["predicted"]:
    assert 0 < p["efficiency"] <= 1.0 + 1e-12, p
    assert p["seconds_generation"] >= p["seconds_compute"], p
    # A whole search is ceil(evaluations / population) generations.
    generations = -(-20000000 // p["population"])
    assert abs(p["seconds_search"] - generations * p["seconds_generation"]) <= 1e-9 * p["seconds_search"], p
print("bench scale: ok (MPI %s)" % ("measured" if mpi else "not built"))
PY
