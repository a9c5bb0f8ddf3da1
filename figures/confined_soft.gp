# The probe's fourth part (make many-body-report draws it; studies/coarse/probe_fourth.hpp): the
# force on a resolved soft-particle pressing the centre while walls at Δn_w confine it, against
# its Δn, mean over the seeds with its standard error, and the soft-soft forms of fourth-version.md
# (the third version's law; volumetric-union and onset-shift fitted again). One radius per figure;
# rows: Δn_w 0.1, 0.2; columns: opposite, tetrahedral (held out), cube.
#
#   gnuplot -e "data='data/many-body/report/fourth-version.dat'; radius=0; out='confined-soft-half.png'" figures/confined_soft.gp
#
# data: blocks '# RADIUS ARRANGEMENT:soft+walls-D' (radii, then D, then arrangements, in that
# order), columns 3 delta_n, 4-5 F measured (mean, se) [N], 6 F third, 7 F volumetric-union,
# 8 F onset-shift. radius: the radius's place among the plan's (0: the first).

if (!exists("data") || !exists("out") || !exists("radius")) {
  print "usage: gnuplot -e \"data='.../fourth-version.dat'; radius=0; out='confined-soft.pdf|png'\" figures/confined_soft.gp"
  exit status 2
}
if (system("test -r '".data."' && echo yes") ne "yes") {
  print "confined_soft.gp: cannot read ".data
  exit status 2
}
if (out[strlen(out)-3:] eq ".pdf") {
  set terminal pdfcairo size 24cm,14cm font "Helvetica,7" linewidth 1.2
} else {
  set terminal pngcairo size 2400,1400 font "Helvetica,18" linewidth 2
}
set output out
set multiplot layout 2,3
set grid
set logscale y
set yrange [1e-4:10]
set xrange [0:0.42]
set key bottom right
set xlabel "{/Symbol D}n of the pressing soft-particle"
set ylabel "F_n on it [N]"
arrangements = "opposite tetrahedral cube"
walls = "0.1 0.2"
do for [d = 1:2] {
  do for [a = 1:3] {
    i = radius * 6 + (d - 1) * 3 + (a - 1)
    set title sprintf("%s, walls at {/Symbol D}n_w = %s", word(arrangements, a), word(walls, d))
    plot data index i using 3:4:5 with yerrorbars pt 7 lc rgb "black" title "measured", \
         ''   index i using 3:6 with lines lw 2 lc rgb "#1f77b4" title "third version", \
         ''   index i using 3:7 with lines lw 2 dt 2 lc rgb "#d62728" title "volumetric-union", \
         ''   index i using 3:8 with lines lw 2 dt 3 lc rgb "#2ca02c" title "onset-shift"
  }
}
unset multiplot
