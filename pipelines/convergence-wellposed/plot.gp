# Both convergence studies, log-log against unknowns (3N): the paper's (RMS against its reference),
# the well-posed one (RMS against the converged reference) and its crack opening's relative error.
# Called with -e "wellposed='convergence.csv'; reference='reference.csv'; paper='../convergence/out/convergence.csv'; png='out.png'".
# Columns: docs/FORMATS.md (convergence.csv, reference.csv).
set terminal pngcairo size 1800,640 font "sans,11"
set output png
set datafile separator ","
# 3 x the RMS between the reference's two finest levels (its second-last row): below, not resolved.
stats reference using 3 skip 1 nooutput
n = STATS_records
stats reference using ($0 == n - 2 ? $3 : 1/0) skip 1 nooutput
limit = 3 * STATS_max
set multiplot layout 1,3
set logscale xy
set grid xtics ytics mxtics mytics
set xlabel "unknowns 3N"
set format y "%.0e"
set key top right
set xrange [500:300000]
set ylabel "RMS error against the reference (m)"
set title "Paper's load (top edge pulled: no mesh-independent limit)\nagainst CG-FEM 18x36x120"
plot paper using (strcol(1) eq "xfem" ? $5 : 1/0):7 skip 1 with linespoints lw 2 pt 7 lc 1 title "X-FEM, unstructured", \
     paper using (strcol(1) eq "xgrid" ? $5 : 1/0):7 skip 1 with linespoints lw 2 pt 9 lc 2 title "X-FEM, structured, not cut-aligned", \
     paper using (strcol(1) eq "cg" ? $5 : 1/0):7 skip 1 with linespoints lw 2 pt 5 lc 3 title "CG-FEM, cut-aligned"
set title "Well-posed load (whole top face pulled)\nagainst CG-FEM 30x60x200 (1.1M unknowns)"
plot wellposed using (strcol(1) eq "xfem" ? $5 : 1/0):7 skip 1 with linespoints lw 2 pt 7 lc 1 title "X-FEM, unstructured", \
     wellposed using (strcol(1) eq "xgrid" ? $5 : 1/0):7 skip 1 with linespoints lw 2 pt 9 lc 2 title "X-FEM, structured, not cut-aligned", \
     wellposed using (strcol(1) eq "cg" ? $5 : 1/0):7 skip 1 with linespoints lw 2 pt 5 lc 3 title "CG-FEM, cut-aligned", \
     limit with lines dt 2 lw 2 lc rgb "gray40" title "3 x reference level difference (below: not resolved)"
set ylabel "relative error of the crack opening at mid-width"
set title "Well-posed load: crack opening against its limit\n(Richardson, from the three reference levels)"
plot wellposed using (strcol(1) eq "xfem" ? $5 : 1/0):12 skip 1 with linespoints lw 2 pt 7 lc 1 title "X-FEM, unstructured", \
     wellposed using (strcol(1) eq "xgrid" ? $5 : 1/0):12 skip 1 with linespoints lw 2 pt 9 lc 2 title "X-FEM, structured, not cut-aligned", \
     wellposed using (strcol(1) eq "cg" ? $5 : 1/0):12 skip 1 with linespoints lw 2 pt 5 lc 3 title "CG-FEM, cut-aligned"
unset multiplot
