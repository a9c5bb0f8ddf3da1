# Figure 2 of the paper: a soft-particle, drawn as the central cross-section of a generated
# packing: every sphere cut by the plane z = 0 as a circle, true to scale, inside the shell.
# Usage: gnuplot -e "data='section.dat'; Rs=0.016; out='fig2.png'" figures/fig2_softparticle.gp
# (out ending in .pdf gives a PDF). Lengths are plotted in mm.
if (!exists("data") || !exists("out") || !exists("Rs")) {
  print "usage: gnuplot -e \"data='section.dat'; Rs=0.016; out='fig2.png'\" figures/fig2_softparticle.gp"
  exit status 2
}
if (out[strlen(out)-3:] eq "pdf") {
  set terminal pdfcairo size 12cm,12cm font "Helvetica,11"
} else {
  set terminal pngcairo size 1400,1400 font "Helvetica,22"
}
set output out
set size ratio -1
mm = 1000.0
R = Rs * mm
set xrange [-1.08 * R : 1.08 * R]
set yrange [-1.08 * R : 1.08 * R]
set xlabel "x [mm]"
set ylabel "y [mm]"
set title "A soft-particle: central cross-section (z = 0) of a generated packing, Rs = ".sprintf("%.0f", R)." mm"
set style fill solid 0.85 border lc rgb "#1f3d5c"
set object 1 circle at 0,0 size R front fillstyle empty border lc rgb "#b22222" lw 3 dt 2
plot data using ($1 * mm):($2 * mm):($3 * mm) with circles lc rgb "#7fa7cf" notitle
