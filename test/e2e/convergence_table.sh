#!/usr/bin/env bash
# scripts/convergence_table.py on synthetic inputs with known answers: the Richardson limit and
# order of q = q0 + C h^p, the reference's error estimate from three levels, and the claim check,
# which must fail when an X-FEM run is above CG-FEM.
set -euo pipefail
T=$XFEM_SOURCE/scripts/convergence_table.py
rm -rf "$XFEM_SCRATCH" && mkdir -p "$XFEM_SCRATCH" && cd "$XFEM_SCRATCH"

# Richardson through three points of q = 0.014 - 0.5 h^1.4 at uneven h: limit and order back.
python3 - "$T" <<'PY'
import sys
src = open(sys.argv[1]).read().split("if __name__")[0]
exec(src)
h = [0.03, 0.022, 0.017]
q0, p = richardson(h, [0.014 - 0.5 * x ** 1.4 for x in h])
assert abs(q0 - 0.014) < 1e-12 and abs(p - 1.4) < 1e-9, (q0, p)
assert richardson(h, [1.0, 1.2, 1.1]) == (None, None)  # not monotone: no fit
PY

# Claim check: X-FEM below CG at equal unknowns passes; one X-FEM run above fails.
header="method,mesh,tets,n_vectors,unknowns,enriched_nodes,rms_m,relative_rms,max_m,solve_s,resolved,opening_error"
{ echo "$header"
  echo "xfem,a,1,1,2000,0,5e-4,0,0,0,yes,"
  echo "xfem,b,1,1,9000,0,1e-4,0,0,0,no,"
  echo "cg,c,1,1,1000,0,1e-3,0,0,0,yes,"
  echo "cg,d,1,1,10000,0,4e-4,0,0,0,yes,"; } > good.csv
python3 "$T" check good.csv 2> out.txt || { cat out.txt >&2; echo "convergence_table: check refused a good table" >&2; exit 1; }
sed 's/^xfem,a,1,1,2000,0,5e-4/xfem,a,1,1,2000,0,9e-4/' good.csv > bad.csv  # CG at 2000 is ~7.6e-4
if python3 "$T" check bad.csv 2> out.txt; then echo "convergence_table: check passed X-FEM above CG-FEM" >&2; exit 1; fi
grep -q "xfem a: RMS 9e-4 at 2000 unknowns" out.txt || { cat out.txt >&2; exit 1; }
echo "convergence_table: ok"
