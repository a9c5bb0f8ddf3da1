# A response study's figure (report kind `response`, studies/report/response_report.hpp): the
# normal force Fn at each compared delta_n, in both scenes, over the reference's, against the
# value of the key the study varies, with the seed-to-seed standard errors. A law that does not
# answer the key is a set of lines at 1; a point where the reference's Fn is not told from zero
# is not drawn.
#
#   gnuplot -e "data='DATA/studies/loading-speed/report/response.dat'; out='response.pdf'" figures/response.gp
#
# data: a header line naming the columns, then one row per setting: 1 the key's value, 2 CPU
# seconds, then for each scene and delta_n: Fn, its error, Fn over the reference's, its error. out: .pdf (pdfcairo, 12 x 9 cm) or .png.

if (!exists("data") || !exists("out")) {
  print "usage: gnuplot -e \"data='.../response.dat'; out='response.pdf|png'\" figures/response.gp"
  exit status 2
}
if (system("test -r '".data."' && echo yes") ne "yes") {
  print "response.gp: cannot read ".data
  exit status 2
}
if (out[strlen(out)-3:] eq ".pdf") {
  set terminal pdfcairo size 12cm,9cm font "Helvetica,7" linewidth 1.2
} else {
  set terminal pngcairo size 2000,1500 font "Helvetica,22" linewidth 3
}
set output out
key = system("sed -n 's/^# Fn \\[N\\] against \\([^ ]*\\).*/\\1/p' '".data."'")
header = system("grep -v '^#' '".data."' | head -1")
curves = (words(header) - 2) / 4
set xlabel key
set ylabel "F_n / F_n of the reference"
set logscale x
set grid
set key outside right
rows = system("grep -v '^#' '".data."' | tail -n +2 | wc -l") + 0
if (rows == 0) {
  unset logscale
  set label 1 "no setting run yet" at graph 0.5, graph 0.5 center
  plot 1/0 notitle
} else {
  dash(i) = i <= curves / 2 ? 1 : 2  # soft-solid solid, soft-soft dashed
  plot for [i=1:curves] data skip 1 using 1:(column(4*i + 1)):(column(4*i + 2)) with yerrorlines pt 7 ps 1.2 lc i \
         dt dash(i) title word(header, 4*i - 1) noenhanced, \
       1 with lines dt 3 lc rgb "black" notitle
}
