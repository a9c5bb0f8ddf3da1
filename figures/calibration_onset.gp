# The calibration study's onset figure (make calibrate; studies/report/calibration_report.hpp): the
# onset δ of Eq. 7 of both scenes against the solid fraction of the setting's packings, one point
# per setting with its seed-to-seed standard errors, labelled; the paper's δ as horizontal lines.
#
#   gnuplot -e "data='data/calibrate/report/onset.dat'; out='onset.pdf'" figures/calibration_onset.gp
#
# data: columns 1 index, 2 setting (quoted), 3 solid fraction, 4 its error, 5 soft-solid δ,
# 6 its error, 7 soft-soft δ, 8 its error, 9 coordination after growth, 10 its error.
# out: .pdf (pdfcairo, 12 x 9 cm) or .png.

if (!exists("data") || !exists("out")) {
  print "usage: gnuplot -e \"data='.../onset.dat'; out='onset.pdf|png'\" figures/calibration_onset.gp"
  exit status 2
}
if (system("test -r '".data."' && echo yes") ne "yes") {
  print "calibration_onset.gp: cannot read ".data
  exit status 2
}
if (out[strlen(out)-3:] eq ".pdf") {
  set terminal pdfcairo size 12cm,9cm font "Helvetica,7" linewidth 1.2
} else {
  set terminal pngcairo size 2000,1500 font "Helvetica,22" linewidth 3
}
set output out
set xlabel "solid fraction of the packings"
set ylabel "onset {/Symbol d} of Eq. 7"
set grid
set key top right
set offsets graph 0.08, graph 0.15, graph 0.1, graph 0.1
stats data using 3 nooutput
if (STATS_records == 0) {
  set label 1 "no setting run yet" at graph 0.5, graph 0.5 center
  plot 1/0 notitle
} else {
  plot data using 3:5:4:6 with xyerrorbars pt 7 ps 0.8 lc rgb "#1f77b4" title "soft-solid", \
       data using 3:5:2 with labels offset char 0.5, char 0.6 left font ",6" tc rgb "#1f77b4" notitle, \
       data using 3:7:4:8 with xyerrorbars pt 5 ps 0.8 lc rgb "#d62728" title "soft-soft", \
       data using 3:7:2 with labels offset char 0.5, char 0.6 left font ",6" tc rgb "#d62728" notitle, \
       0.065 with lines dt 2 lc rgb "#1f77b4" title "paper, soft-solid (0.065)", \
       0.148 with lines dt 2 lc rgb "#d62728" title "paper, soft-soft (0.148)"
}
