# RMS error against unknowns (3N), log-log, like the paper's figure 9.
# Called with -e "csv='in.csv'; png='out.png'". Columns: see scripts/convergence_table.py.
set terminal pngcairo size 900,620 font "sans,12"
set output png
set datafile separator ","
set logscale xy
set grid xtics ytics mxtics mytics
set xlabel "unknowns 3N"
set ylabel "RMS error against the reference (m)"
set title "Beam benchmark: X-FEM on unstructured meshes vs CG-FEM on cut-aligned grids"
set key top right
plot csv using (strcol(1) eq "xfem" ? $5 : 1/0):7 skip 1 with linespoints lw 2 pt 7 title "X-FEM (unstructured, not cut-aligned)", \
     csv using (strcol(1) eq "xgrid" ? $5 : 1/0):7 skip 1 with linespoints lw 2 pt 9 title "X-FEM (structured grid, not cut-aligned)", \
     csv using (strcol(1) eq "cg" ? $5 : 1/0):7 skip 1 with linespoints lw 2 pt 5 title "CG-FEM (cut-aligned, doubled nodes)"
