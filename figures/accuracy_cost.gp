# The fidelity study's figure: the error of each setting against the CPU time of its measurement
# (make accuracy; studies/report/accuracy_report.hpp). One point per setting, labelled; the Pareto
# front (no other setting both cheaper and more accurate) joined by a line; the paper's literal
# protocol (the setting "paper") marked.
#
#   gnuplot -e "data='data/accuracy/report/pareto.dat'; out='accuracy-cost.pdf'" figures/accuracy_cost.gp
#
# data: columns 1 index, 2 setting (quoted), 3 CPU [s], 4 CPU / paper's, 5 max |z|, 6 rms z,
# 7 on the Pareto front (0/1), 8 runs (1) or is a subset of another's seeds (0). z: the error in
# units of the reference's seed-to-seed standard error. out: .pdf (pdfcairo, 12 x 9 cm) or .png.

if (!exists("data") || !exists("out")) {
  print "usage: gnuplot -e \"data='.../pareto.dat'; out='accuracy-cost.pdf|png'\" figures/accuracy_cost.gp"
  exit status 2
}
if (system("test -r '".data."' && echo yes") ne "yes") {
  print "accuracy_cost.gp: cannot read ".data
  exit status 2
}
if (out[strlen(out)-3:] eq ".pdf") {
  set terminal pdfcairo size 12cm,9cm font "Helvetica,7" linewidth 1.2
} else {
  set terminal pngcairo size 2000,1500 font "Helvetica,22" linewidth 3
}
set output out
set logscale xy
set xlabel "CPU time of the measurement [s]"
set ylabel "largest error |z| (units of the reference's seed-to-seed standard error)"
set grid
set key top right
set offsets graph 0.05, graph 0.15, graph 0.1, graph 0.1
# A floor for settings that agree exactly (z = 0 cannot be drawn on a log axis).
zfloor(z) = z > 1e-3 ? z : 1e-3
stats data using 3 nooutput
if (STATS_records == 0) {
  set label 1 "no setting run yet" at graph 0.5, graph 0.5 center
  plot 1/0 notitle
} else {
  plot data using 3:(zfloor($5)) with points pt 7 ps 0.8 lc rgb "#555555" title "setting", \
       data using 3:(zfloor($5)):2 with labels offset char 0.5, char 0.6 left font ",6" notitle, \
       "< awk '$7 == 1' ".data." | sort -g -k3" using 3:(zfloor($5)) with linespoints pt 7 ps 1 lc rgb "#1f77b4" title "Pareto front", \
       "< awk '$2 == \"\\\"paper\\\"\"' ".data using 3:(zfloor($5)) with points pt 6 ps 2.5 lw 2 lc rgb "#d62728" title "the paper's protocol", \
       1 with lines dt 2 lc rgb "#2ca02c" title "one standard error"
}
