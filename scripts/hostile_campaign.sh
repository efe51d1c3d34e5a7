#!/usr/bin/env bash
# Hostile-input campaign: every input file of the beam pipeline, truncated and byte-flipped, fed
# to the tool that reads it. Each run must end in exit 0, or exit 1/2 with exactly one line
# "<tool>: error: ..." / "<tool>: usage error: ..." on stderr; a signal (crash, sanitizer abort),
# a hang (over TIMEOUT s), another exit code or another stderr is a defect. Prints one line per
# (tool, input) with the counts, then the defects; exits 1 if there is any.
#   scripts/hostile_campaign.sh BIN_DIR [MUTATIONS_PER_FILE=30] [WORK_DIR=/tmp/xfem-campaign]
# With the ASan + UBSan tools (build-asan/tools) a sanitizer report is a crash too.
# KS="0 5 9 ..." runs those mutations only, instead of 0 .. MUTATIONS_PER_FILE - 1 (the short form
# test/e2e/hostile_campaign.sh runs in CI). Covers the beam pipeline's stages (round one) and the
# tools and inputs added since (round two, issue 36): xfem-newton (material.model, load_steps),
# xfem-front, xfem-probe, xfem-sweep, xfem-mesh surface and cut-merge, gmsh .msh files (MSH 2.2
# and 4.1, ASCII and binary), legacy VTK meshes, Dirichlet conditions with rotation and value_array.
set -u
B=${1:?usage: hostile_campaign.sh BIN_DIR [MUTATIONS] [WORK_DIR]}
N=${2:-30}
W=${3:-/tmp/xfem-campaign}
KS=${KS:-$(seq 0 $((N - 1)))}
N=$(echo $KS | wc -w)
TIMEOUT=${TIMEOUT:-120}
SRC=$(cd "$(dirname "$0")/.." && pwd)
PROBLEM=$SRC/pipelines/beam/problem.json
EXACT=$SRC/pipelines/verification/data/rigid_exact.json
rm -rf "$W"; mkdir -p "$W/good" "$W/bad"
G=$W/good
"$B/xfem-mesh" -q box --cells 2 3 8 --hi 0.03 0.06 0.2 -o "$G/beam.vtu" &&
  "$B/xfem-mesh" -q cut-rect --beam-cut -o "$G/cut.vtp" &&
  "$B/xfem-classify" -q "$G/beam.vtu" --cut "$G/cut.vtp" -o "$G/classified.vtu" &&
  "$B/xfem-enrich" -q "$G/classified.vtu" -o "$G/enriched.vtu" &&
  "$B/xfem-assemble" -q "$G/enriched.vtu" --cut "$G/cut.vtp" --problem "$PROBLEM" --format mtx -o "$G/system" &&
  "$B/xfem-solve" -q "$G/system" -o "$G/u.mtx" &&
  cp "$PROBLEM" "$G/problem.json" && cp "$EXACT" "$G/exact.json" || { echo "campaign: the good pipeline failed" >&2; exit 1; }

# Round two's good inputs: a non-linear problem (neo-Hookean in two load steps) and its solution, a
# rotation Dirichlet condition, a legacy VTK mesh with a point array for value_array, gmsh files, a
# sweep with its times, probe points, a closed surface, a second cut.
python3 - "$G" <<'EOF' || { echo "campaign: writing round two's inputs failed" >&2; exit 1; }
import itertools, json, sys
g = sys.argv[1]
p = json.load(open(g + "/problem.json"))
nl = dict(p, material=dict(p["material"], model="neo-hookean"), load_steps=2)
json.dump(nl, open(g + "/problem_nl.json", "w"), indent=1)
rot = dict(p)
rot["dirichlet"] = [p["dirichlet"][0], {"name": "turned end", "selector": p["dirichlet"][1]["selector"],
                    "rotation": {"axis": [1, 0, 0], "angle_deg": 2, "center": [0.015, 0.03, 0.2], "translation": [0, 0, 0.001]}}]
json.dump(rot, open(g + "/problem_rot.json", "w"), indent=1)
n, h = 2, 0.01
idx = lambda i, j, k: i + (n + 1) * (j + (n + 1) * k)
pts = [(i * h, j * h, k * h) for k in range(n + 1) for j in range(n + 1) for i in range(n + 1)]
tets = []
for i, j, k in itertools.product(range(n), repeat=3):
    for perm in itertools.permutations(range(3)):
        c = [i, j, k]; v = [idx(*c)]
        for a in perm:
            c[a] += 1; v.append(idx(*c))
        q = [pts[m] for m in v]
        e = [[q[m][r] - q[0][r] for r in range(3)] for m in (1, 2, 3)]
        det = (e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0])
               + e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]))
        tets.append(v if det > 0 else [v[0], v[2], v[1], v[3]])
bnd = [int(any(abs(x) < 1e-12 or abs(x - n * h) < 1e-12 for x in q)) for q in pts]
measured = [0.01 * q[r] if b else 0.0 for q, b in zip(pts, bnd) for r in range(3)]
with open(g + "/field.vtk", "w") as f:
    f.write("# vtk DataFile Version 3.0\nfield\nASCII\nDATASET UNSTRUCTURED_GRID\n")
    f.write("POINTS %d double\n" % len(pts) + "".join("%r %r %r\n" % q for q in pts))
    f.write("CELLS %d %d\n" % (len(tets), 5 * len(tets)) + "".join("4 %d %d %d %d\n" % tuple(t) for t in tets))
    f.write("CELL_TYPES %d\n" % len(tets) + "10\n" * len(tets))
    f.write("POINT_DATA %d\nSCALARS boundary double 1\nLOOKUP_TABLE default\n" % len(pts) + "".join("%d\n" % b for b in bnd))
    f.write("VECTORS measured double\n" + "".join("%r %r %r\n" % tuple(measured[3 * m:3 * m + 3]) for m in range(len(pts))))
json.dump({"material": {"E": 1e3, "nu": 0.3}, "dirichlet": [{"selector": {"point_array": "boundary"}, "value_array": "measured"}]},
          open(g + "/value_array.json", "w"))
with open(g + "/points.csv", "w") as f:
    f.write("x,y,z,side\n0.015,0.03,0.05,0\n0.01,0.02,0.099,-1\n0.01,0.02,0.101,1\n")
c = [(x, y, z) for z in (0, 0.02) for y in (0, 0.02) for x in (0, 0.02)]
quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
with open(g + "/box.off", "w") as f:
    f.write("OFF\n8 12 0\n" + "".join("%r %r %r\n" % q for q in c))
    f.write("".join("3 %d %d %d\n3 %d %d %d\n" % (a, b, cc, a, cc, d) for a, b, cc, d in quads))
EOF
"$B/xfem-newton" -q "$G/enriched.vtu" --cut "$G/cut.vtp" -p "$G/problem_nl.json" -o "$G/u_nl.mtx" &&
  "$B/xfem-classify" -q "$G/field.vtk" -o "$G/va_classified.vtu" &&
  "$B/xfem-enrich" -q "$G/va_classified.vtu" -o "$G/va_enriched.vtu" &&
  "$B/xfem-mesh" -q cut-sweep --path -0.01 0.03 0.21 0.04 0.03 0.21 --depth 0.06 --resolution 0.01 -o "$G/sweep.vtp" &&
  "$B/xfem-mesh" -q cut-rect --corner -0.01 -0.01 0.05 --edge1 0.05 0 0 --edge2 0 0.03 0 -o "$G/second.vtp" &&
  "$B/xfem-mesh" -q cut-rect --corner -0.01 -0.01 0.11 --edge1 0.05 0 0 --edge2 0 0.04 0 -o "$G/partial.vtp" &&
  "$B/xfem-classify" -q "$G/beam.vtu" --cut "$G/partial.vtp" -o "$G/p_classified.vtu" &&
  "$B/xfem-enrich" -q "$G/p_classified.vtu" -o "$G/p_enriched.vtu" &&
  "$B/xfem-assemble" -q "$G/p_enriched.vtu" --cut "$G/partial.vtp" --problem "$PROBLEM" --format mtx -o "$G/p_system" &&
  "$B/xfem-solve" -q "$G/p_system" -o "$G/p_u.mtx" &&
  "$B/xfem-front" -q "$G/p_enriched.vtu" --cut "$G/partial.vtp" -s "$G/p_u.mtx" -p "$G/problem.json" --csv "$W/front.csv" &&
  cp "$SRC/test/data/gmsh/cube22.msh" "$SRC/test/data/gmsh/cube41.msh" "$SRC/test/data/gmsh/cube41_bin.msh" \
     "$SRC/test/data/gmsh/cube22_bin.msh" "$G/" || { echo "campaign: round two's good pipeline failed" >&2; exit 1; }

# mutate IN OUT K: the K-th mutation: truncation (K < 8, at K/8 of the size), else one to four
# bytes set to random values (seeded by K, reproducible).
mutate() {
  python3 - "$1" "$2" "$3" <<'EOF'
import random, sys
data = bytearray(open(sys.argv[1], 'rb').read()); k = int(sys.argv[3]); r = random.Random(k)
if k < 8:
    data = data[:len(data) * k // 8]
else:
    for _ in range(r.randint(1, 4)):
        i = r.randrange(len(data)); data[i] = r.choice([r.randrange(256), ord(r.choice('0123456789-+.eE \n"{}[],:'))])
open(sys.argv[2], 'wb').write(data)
EOF
}

defects=()
# attack TOOL FILE (in good/) COMMAND...: COMMAND reads $BAD (a mutated copy of FILE, same name) or
# $BADDIR (a copy of the system directory with FILE replaced).
attack() {
  local tool=$1 file=$2; shift 2
  local ok=0 refused=0 bad=0
  for k in $KS; do
    local case=$W/bad/$tool-$(basename "$file")-$k
    rm -rf "$case"; mkdir -p "$case/out"
    if [[ $file == system/* ]]; then
      cp -r "$G/system" "$case/system"; mutate "$G/$file" "$case/$file" "$k"
    else
      mutate "$G/$file" "$case/$(basename "$file")" "$k"
    fi
    BAD=$case/$(basename "$file") BADDIR=$case/system OUT=$case/out \
      timeout -s KILL "$TIMEOUT" "$@" >"$case/stdout" 2>"$case/stderr"
    local rc=$?
    if [ $rc -eq 0 ]; then
      ok=$((ok + 1))
    elif { [ $rc -eq 1 ] || [ $rc -eq 2 ]; } && [ "$(wc -l <"$case/stderr")" -eq 1 ] &&
         grep -q "^$tool: \(usage \)\?error: " "$case/stderr"; then
      refused=$((refused + 1))
    else
      bad=$((bad + 1))
      defects+=("$tool $file #$k: exit $rc: $(head -c 300 "$case/stderr" | tr '\n' ' ')")
      continue
    fi
    rm -rf "$case"
  done
  printf '%-16s %-22s tried %3d  exit 0 %3d  refused %3d  defects %d\n' "$tool" "$file" "$N" "$ok" "$refused" "$bad"
}

export B G
attack xfem-classify beam.vtu sh -c '"$B/xfem-classify" -q "$BAD" --cut "$G/cut.vtp" -o "$OUT/c.vtu"'
attack xfem-classify cut.vtp sh -c '"$B/xfem-classify" -q "$G/beam.vtu" --cut "$BAD" -o "$OUT/c.vtu"'
attack xfem-enrich classified.vtu sh -c '"$B/xfem-enrich" -q "$BAD" -o "$OUT/e.vtu"'
attack xfem-assemble enriched.vtu sh -c '"$B/xfem-assemble" -q "$BAD" --cut "$G/cut.vtp" --problem "$G/problem.json" -o "$OUT/s"'
attack xfem-assemble problem.json sh -c '"$B/xfem-assemble" -q "$G/enriched.vtu" --cut "$G/cut.vtp" --problem "$BAD" -o "$OUT/s"'
for f in K.mtx f.mtx dirichlet.mtx coordinates.mtx system.json provenance.json; do
  [ -e "$G/system/$f" ] && attack xfem-solve "system/$f" sh -c '"$B/xfem-solve" -q "$BADDIR" -o "$OUT/u.mtx"'
done
attack xfem-visualize u.mtx sh -c '"$B/xfem-visualize" -q "$G/enriched.vtu" --cut "$G/cut.vtp" -s "$BAD" -p "$G/problem.json" -o "$OUT/d.vtu"'
attack xfem-visualize problem.json sh -c '"$B/xfem-visualize" -q "$G/enriched.vtu" --cut "$G/cut.vtp" -s "$G/u.mtx" -p "$BAD" -o "$OUT/d.vtu"'
attack xfem-rmserror u.mtx sh -c '"$B/xfem-rmserror" -q "$G/enriched.vtu" --cut "$G/cut.vtp" -s "$BAD" --exact "$G/exact.json"'
attack xfem-rmserror exact.json sh -c '"$B/xfem-rmserror" -q "$G/enriched.vtu" --cut "$G/cut.vtp" -s "$G/u.mtx" --exact "$BAD"'
attack xfem-rmserror enriched.vtu sh -c '"$B/xfem-rmserror" -q "$BAD" --cut "$G/cut.vtp" -s "$G/u.mtx" --exact "$G/exact.json"'

# Round two (issue 36): the tools and inputs added since.
attack xfem-newton problem_nl.json sh -c '"$B/xfem-newton" -q "$G/enriched.vtu" --cut "$G/cut.vtp" -p "$BAD" -o "$OUT/u.mtx"'
attack xfem-newton enriched.vtu sh -c '"$B/xfem-newton" -q "$BAD" --cut "$G/cut.vtp" -p "$G/problem_nl.json" -o "$OUT/u.mtx"'
attack xfem-visualize u_nl.mtx sh -c '"$B/xfem-visualize" -q "$G/enriched.vtu" --cut "$G/cut.vtp" -s "$BAD" -p "$G/problem_nl.json" -o "$OUT/d.vtu" --faces "$OUT/w.vtp"'
attack xfem-assemble problem_rot.json sh -c '"$B/xfem-assemble" -q "$G/enriched.vtu" --cut "$G/cut.vtp" --problem "$BAD" -o "$OUT/s"'
attack xfem-assemble value_array.json sh -c '"$B/xfem-assemble" -q "$G/va_enriched.vtu" --problem "$BAD" -o "$OUT/s"'
attack xfem-classify field.vtk sh -c '"$B/xfem-classify" -q "$BAD" -o "$OUT/c.vtu"'
for f in cube22.msh cube22_bin.msh cube41.msh cube41_bin.msh; do
  attack xfem-classify $f sh -c '"$B/xfem-classify" -q "$BAD" --cut "$G/cut.vtp" -o "$OUT/c.vtu"'
done
# xfem-front on a cut whose front lies inside the beam (partial.vtp, its p_ pipeline).
attack xfem-front p_u.mtx sh -c '"$B/xfem-front" -q "$G/p_enriched.vtu" --cut "$G/partial.vtp" -s "$BAD" -p "$G/problem.json" --csv "$OUT/f.csv"'
attack xfem-front p_enriched.vtu sh -c '"$B/xfem-front" -q "$BAD" --cut "$G/partial.vtp" -s "$G/p_u.mtx" -p "$G/problem.json" --csv "$OUT/f.csv"'
attack xfem-front problem.json sh -c '"$B/xfem-front" -q "$G/p_enriched.vtu" --cut "$G/partial.vtp" -s "$G/p_u.mtx" -p "$BAD" --csv "$OUT/f.csv"'
attack xfem-front partial.vtp sh -c '"$B/xfem-front" -q "$G/p_enriched.vtu" --cut "$BAD" -s "$G/p_u.mtx" -p "$G/problem.json" --csv "$OUT/f.csv"'
attack xfem-probe u.mtx sh -c '"$B/xfem-probe" -q "$G/enriched.vtu" --cut "$G/cut.vtp" -s "$BAD" -p "$G/points.csv" -o "$OUT/p.csv"'
attack xfem-probe points.csv sh -c '"$B/xfem-probe" -q "$G/enriched.vtu" --cut "$G/cut.vtp" -s "$G/u.mtx" -p "$BAD" -o "$OUT/p.csv"'
attack xfem-probe enriched.vtu sh -c '"$B/xfem-probe" -q "$BAD" --cut "$G/cut.vtp" -s "$G/u.mtx" -p "$G/points.csv" -o "$OUT/p.csv"'
attack xfem-sweep sweep.vtp sh -c '"$B/xfem-sweep" -q "$G/beam.vtu" --cut "$BAD" -p "$G/problem.json" --steps 2 -o "$OUT/frames"'
attack xfem-sweep beam.vtu sh -c '"$B/xfem-sweep" -q "$BAD" --cut "$G/sweep.vtp" -p "$G/problem.json" --steps 2 -o "$OUT/frames"'
attack xfem-sweep problem.json sh -c '"$B/xfem-sweep" -q "$G/beam.vtu" --cut "$G/sweep.vtp" -p "$BAD" --steps 2 -o "$OUT/frames"'
attack xfem-mesh box.off sh -c '"$B/xfem-mesh" -q surface "$BAD" --size 0.01 -o "$OUT/m.vtu"'
attack xfem-mesh second.vtp sh -c '"$B/xfem-mesh" -q cut-merge "$G/cut.vtp" "$BAD" --cut-id -o "$OUT/m.vtp"'

if [ ${#defects[@]} -gt 0 ]; then
  echo "defects (inputs kept in $W/bad):"
  printf '  %s\n' "${defects[@]}"
  exit 1
fi
echo "no defects"
