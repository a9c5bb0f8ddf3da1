# The radius study's friction figure (make radius; studies/report/radius_report.hpp): the
# soft-particle's friction coefficient mu_soft = Ft / Fn on the sliding plateau against delta_n,
# one curve per setting and scene, with the seed-to-seed standard errors; the grains' mu = 0.3
# dashed (the paper expects mu_soft to be larger).
#
#   gnuplot -e "data='data/radius/report/friction.dat'; out='friction.pdf'" figures/radius_friction.gp
#
# data: columns 1 setting, 2 scene, 3 Rs/R0, 4 delta_n, 5 mu_soft, 6 its error, 7 the largest
# Ft/Fn, 8 its error. out: .pdf (pdfcairo, 12 x 9 cm) or .png.

if (!exists("data") || !exists("out")) {
  print "usage: gnuplot -e \"data='.../friction.dat'; out='friction.pdf|png'\" figures/radius_friction.gp"
  exit status 2
}
if (system("test -r '".data."' && echo yes") ne "yes") {
  print "radius_friction.gp: cannot read ".data
  exit status 2
}
if (out[strlen(out)-3:] eq ".pdf") {
  set terminal pdfcairo size 12cm,9cm font "Helvetica,7" linewidth 1.2
} else {
  set terminal pngcairo size 2000,1500 font "Helvetica,22" linewidth 3
}
set output out
set xlabel "{/Symbol D}_n"
set ylabel "{/Symbol m}_{soft} = F_t / F_n while sliding"
set grid
set key outside right
set offsets graph 0.05, graph 0.05, graph 0.1, graph 0.1
settings = system("awk '!/^#/ { print $1 }' '".data."' | awk '!seen[$0]++'")
sel(s, c) = (strcol(1) eq s && strcol(2) eq c) ? 1 : NaN
stats data using 4 nooutput
if (STATS_records == 0) {
  set label 1 "no setting run yet" at graph 0.5, graph 0.5 center
  plot 1/0 notitle
} else {
  plot for [i=1:words(settings)] data using 4:($5*sel(word(settings,i),"soft-solid")):6 with yerrorlines pt 7 ps 1.5 lc i \
         title word(settings,i)." soft-solid", \
       for [i=1:words(settings)] data using 4:($5*sel(word(settings,i),"soft-soft")):6 with yerrorlines pt 5 ps 1.5 dt 2 lc i \
         title word(settings,i)." soft-soft", \
       0.3 with lines dt 3 lw 2 lc rgb "black" title "grains' {/Symbol m} = 0.3"
}
