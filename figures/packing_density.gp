# The packing density study (experiments/packing-density.yaml): solid fraction, fitted size
# exponent and depletion next to the shell against beta, I and r_max/Rs (one at a time).
# Usage: gnuplot -e "data='packing-density.dat'; out='packing-density.png'" figures/packing_density.gp
if (!exists("data") || !exists("out")) {
  print "usage: gnuplot -e \"data='packing-density.dat'; out='packing-density.png'\" figures/packing_density.gp"
  exit status 2
}
if (out[strlen(out)-3:] eq "pdf") {
  set terminal pdfcairo size 24cm,20cm font "Helvetica,10"
} else {
  set terminal pngcairo size 1800,1500 font "Helvetica,16"
}
set output out
set multiplot layout 3,3 title "Packing generator: effect of {/Symbol b}, I and r_{max}/R_s (mean ± s.e. over seeds)"
set grid
set key off
set bars small
# columns: 1 parameter, 2 value, 3/4 spheres, 5/6 solid fraction, 7/8 exponent, 9/10 depletion [m]
do for [b = 1:3] {
  if (b == 2) { set logscale x } else { unset logscale x }
  set xlabel (b == 1 ? "{/Symbol b} = V_L / V_S" : (b == 2 ? "trials I" : "r_{max} / R_s"))
  set ylabel "solid fraction"
  plot data index (b-1) using 2:5:6 with yerrorlines lw 2 pt 7
  set ylabel "fitted exponent b"
  plot data index (b-1) using 2:7:8 with yerrorlines lw 2 pt 7, 3.5 dt 2 lc rgb "gray"
  set ylabel "depletion length [mm]"
  plot data index (b-1) using 2:($9*1000):($10*1000) with yerrorlines lw 2 pt 7
}
unset multiplot
