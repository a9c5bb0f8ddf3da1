# The calibration study's sensitivity figure (make calibrate; studies/report/calibration_report.hpp):
# the coefficient change per parameter change. One row per setting, one column per quantity;
# the colour is the change against the base in units of its standard error,
# z = (setting - base) / sqrt(sigma^2 + sigma_base^2) (clipped at +-10), the label the relative
# change in percent. Blank: not measured (e.g. the soft-soft law where too few points are loaded).
#
#   gnuplot -e "data='data/calibrate/report/sensitivity.dat'; out='sensitivity.pdf'" figures/calibration_sensitivity.gp
#
# data: columns 1 quantity index, 2 setting index, 3 z, 4 relative change, 5 setting (quoted),
# 6 quantity (quoted). out: .pdf (pdfcairo, 16 x 12 cm) or .png.

if (!exists("data") || !exists("out")) {
  print "usage: gnuplot -e \"data='.../sensitivity.dat'; out='sensitivity.pdf|png'\" figures/calibration_sensitivity.gp"
  exit status 2
}
if (system("test -r '".data."' && echo yes") ne "yes") {
  print "calibration_sensitivity.gp: cannot read ".data
  exit status 2
}
if (out[strlen(out)-3:] eq ".pdf") {
  set terminal pdfcairo size 16cm,12cm font "Helvetica,7" linewidth 1.2
  small = 6; tiny = 5
} else {
  set terminal pngcairo size 2400,1800 font "Helvetica,20" linewidth 3
  small = 17; tiny = 15
}
set output out
rows = int(system("grep -vc '^#' '".data."' || true"))
if (rows == 0) {
  set label 1 "no setting run yet" at graph 0.5, graph 0.5 center
  unset border; unset tics
  set xrange [0:1]; set yrange [0:1]
  plot 1/0 notitle
} else {
  stats data using 1:2 nooutput
  ncol = int(STATS_max_x) + 1
  nrow = int(STATS_max_y) + 1
  set xrange [-0.5:ncol - 0.5]
  set yrange [nrow - 0.5:-0.5]
  set cbrange [-10:10]
  set cblabel "change / standard error (z)"
  set palette defined (-10 "#2166ac", -2 "#d1e5f0", 0 "#f7f7f7", 2 "#fddbc7", 10 "#b2182b")
  set xtics rotate by 35 right scale 0 font ",".small
  set ytics scale 0 font ",".small
  unset key
  clip(z) = z > 10 ? 10 : (z < -10 ? -10 : z)
  set style fill solid 1.0 noborder
  plot data using 1:2:(0.5):(0.5):(clip($3)):xtic(6):ytic(5) with boxxyerror lc palette, \
       data using 1:2:(valid(4) ? sprintf("%+.0f%%", 100 * $4) : "") with labels font ",".tiny
}
