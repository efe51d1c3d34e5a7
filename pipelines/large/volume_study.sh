#!/usr/bin/env bash
# The organ's 5 cm lift (pipelines/organ/problem.json, the top of the cut side lifted 0.05 m, 5
# load steps, neo-Hookean): the volume the body keeps, on several meshes and for several nu
# (docs/VERIFICATION.md "Large deformation", "The organ's volume"). Per run one row: the mesh,
# nu, Newton's iterations, the volume change of xfem-visualize's deformed.vtu (straight-edged cells
# through the moved corners) and on xfem-newton's integration points (sum of w det F) for the whole
# body and per kind of tet (plain, sign-enriched, branch-enriched), and the largest det F of a
# point carrying volume with its tet's centroid. Measured by hand (minutes per mesh), not a test.
# Usage: pipelines/large/volume_study.sh "SIZES" "NUS" [LIFT=0.05] [LOAD_STEPS=5]
#   e.g. pipelines/large/volume_study.sh "0.012 0.009 0.006" "0.45 0.49"; env: BUILD (default build).
set -eu
sizes=${1:-0.012 0.009}
nus=${2:-0.45}
lift=${3:-0.05}
steps=${4:-5}
build=${BUILD:-build}
B=$(cd "$build/tools" && pwd)
source_dir=$(cd "$(dirname "$0")/../.." && pwd)
tmp=${KEEP:-$(mktemp -d)}
mkdir -p "$tmp"
[ -n "${KEEP:-}" ] || trap 'rm -rf "$tmp"' EXIT
cd "$tmp"
"$B/xfem-mesh" -q cut-sine -o cut.vtp
printf '%-6s %-7s %-5s %-10s %-12s %-12s %-8s %-8s %-8s %s\n' size tets nu iterations deformed.vtu points plain sign branch "max det F (tet centroid, m)"
for size in $sizes; do
  "$B/xfem-mesh" -q organ --size "$size" -o organ-$size.vtu
  "$B/xfem-classify" -q organ-$size.vtu --cut cut.vtp -o classified-$size.vtu
  "$B/xfem-enrich" -q classified-$size.vtu -o enriched-$size.vtu
  for nu in $nus; do
    run=$size-$nu
    python3 - "$source_dir/pipelines/organ/problem.json" "$lift" "$steps" "$nu" problem-$run.json <<'PY'
import json, sys
p = json.load(open(sys.argv[1]))
p['dirichlet'][1]['value'] = [None, None, float(sys.argv[2])]
p['material'].update(model='neo-hookean', nu=float(sys.argv[4]))
p['load_steps'] = int(sys.argv[3])
json.dump(p, open(sys.argv[5], 'w'))
PY
    "$B/xfem-newton" -q enriched-$size.vtu --cut cut.vtp --problem problem-$run.json -o u-$run.mtx --report newton-$run.json
    "$B/xfem-visualize" enriched-$size.vtu --cut cut.vtp --solution u-$run.mtx --problem problem-$run.json \
      -o deformed-$run.vtu 2>visualize-$run.txt
    python3 - "$size" "$nu" newton-$run.json visualize-$run.txt <<'PY'
import json, re, sys
size, nu, report, vis = sys.argv[1:]
r = json.load(open(report))
v = r['volume']
m = re.search(r'volume (\S+) m\^3 -> (\S+) m\^3', open(vis).read())
vtu = float(m.group(2)) / float(m.group(1)) - 1
pct = lambda x: f"{100 * x:+.3f}%"
c, b = v['body']['max_det_F_centroid'], v['body']
print(f"{size:<6} {v['body']['tets']:<7} {nu:<5} {r['newton_iterations']:<10} {pct(vtu):<12} "
      f"{pct(v['body']['relative_change']):<12} {pct(v['plain_tets']['relative_change']):<8} "
      f"{pct(v['sign_tets']['relative_change']):<8} {pct(v['branch_tets']['relative_change']):<8} "
      f"{b['max_det_F']:.4f} (tet {b['max_det_F_tet']} at {c[0]:.4f} {c[1]:.4f} {c[2]:.4f})")
p = v['plain_tets']; cp = p['max_det_F_centroid']
print(f"       largest det F in a plain tet {p['max_det_F']:.4f} (at {cp[0]:.4f} {cp[1]:.4f} {cp[2]:.4f}), in a sign-enriched tet {v['sign_tets']['max_det_F']:.4f}")
print(f"       volume shares: plain {v['plain_tets']['before'] / v['body']['before']:.4f}, sign {v['sign_tets']['before'] / v['body']['before']:.4f}, branch {v['branch_tets']['before'] / v['body']['before']:.4f}; excess (m^3) plain {v['plain_tets']['after'] - v['plain_tets']['before']:.3e}, sign {v['sign_tets']['after'] - v['sign_tets']['before']:.3e}, branch {v['branch_tets']['after'] - v['branch_tets']['before']:.3e}")
PY
  done
done
