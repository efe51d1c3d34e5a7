# Relative L2 error vs DOFs (3N) of out/verification.csv: one panel per mode, the paper's rule and
# radius enrichment on structured and unstructured meshes. Called with csv='...' png='...'.
set terminal pngcairo size 1500,500 font ",10"
set output png
set datafile separator ","
set logscale xy
set format y "%.0e"
set grid
set key bottom left
set xlabel "DOFs (3N)"
set multiplot layout 1,3
do for [m in "mode1 mode2 mode3"] {
  set title "Williams ".m." (relative L2 error)"
  set ylabel "relative L2 error"
  plot for [f in "structured unstructured"] for [r in "paper radius"] \
    csv using ((strcol(1) eq f && strcol(3) eq r && strcol(4) eq m) ? $5 : 1/0):8 \
    with linespoints title f." ".r
}
unset multiplot
