# The radius study's scaling figure (make radius; studies/report/radius_report.hpp): the normal
# force at fixed delta_n against the shell radius, both relative to the reference (R0 = 16 mm),
# for the self-similar and the fixed-grain soft-particles of both scenes, with the seed-to-seed
# standard errors; (R/R0)^2 (Hertz's law of a solid sphere, and any self-similar packing) dashed.
#
#   gnuplot -e "data='data/radius/report/scaling.dat'; out='scaling.pdf'" figures/radius_scaling.gp
#
# data: columns 1 variant (self_similar, fixed), 2 scene, 3 R/R0, then Fn/Fn(R0) and its error
# at each compared delta_n (the header names them); k (default 3) picks the pair: column 2k+2.
# out: .pdf (pdfcairo, 12 x 9 cm) or .png.

if (!exists("data") || !exists("out")) {
  print "usage: gnuplot -e \"data='.../scaling.dat'; out='scaling.pdf|png'\" figures/radius_scaling.gp"
  exit status 2
}
if (system("test -r '".data."' && echo yes") ne "yes") {
  print "radius_scaling.gp: cannot read ".data
  exit status 2
}
if (!exists("k")) k = 3
if (out[strlen(out)-3:] eq ".pdf") {
  set terminal pdfcairo size 12cm,9cm font "Helvetica,7" linewidth 1.2
} else {
  set terminal pngcairo size 2000,1500 font "Helvetica,22" linewidth 3
}
set output out
header = system("head -1 '".data."'")
set title "F_n at fixed {/Symbol D}_n against the radius (pair ".k." of: ".header[strstrt(header, "delta_n ="):].")"
set xlabel "R / R_0"
set ylabel "F_n(R) / F_n(R_0)"
set logscale xy
set grid
set key top left
set xrange [0.35:5.5]
y = 2*k + 2
sel(v, s) = (strcol(1) eq v && strcol(2) eq s) ? 1 : NaN
stats data using 3 nooutput
if (STATS_records == 0) {
  set label 1 "no setting run yet" at graph 0.5, graph 0.5 center
  plot 1/0 notitle
} else {
  plot data using 3:(column(y)*sel("self_similar","soft-solid")):(column(y+1)) with yerrorlines pt 7 lc rgb "#1f77b4" title "self-similar, soft-solid", \
       data using 3:(column(y)*sel("self_similar","soft-soft")):(column(y+1)) with yerrorlines pt 5 lc rgb "#d62728" title "self-similar, soft-soft", \
       data using 3:(column(y)*sel("fixed","soft-solid")):(column(y+1)) with yerrorlines pt 6 dt 3 lc rgb "#1f77b4" title "fixed grains, soft-solid", \
       data using 3:(column(y)*sel("fixed","soft-soft")):(column(y+1)) with yerrorlines pt 4 dt 3 lc rgb "#d62728" title "fixed grains, soft-soft", \
       x**2 with lines dt 2 lc rgb "black" title "(R/R_0)^2"
}
