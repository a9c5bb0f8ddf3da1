# Figure 6: the tangential spring constant kt (slope of Ft,parallel against ht around ht = 0)
# against the normal deformation Δn, both scenes, with the fits of Eq. 8.
#
#   gnuplot -e "avg='data/paper/average'; out='data/paper/figures/fig6_kt.pdf'" \
#           -e "kt_a_solid=160; kt_b_solid=2.6; kt_c_solid=-1.7; kt_delta_solid=0.173" \
#           -e "kt_a_soft=60; kt_b_soft=6.0; kt_c_soft=-0.25; kt_delta_soft=0.401" figures/fig6_kt.gp
#
# Required: avg (the folder with kt-soft-solid.dat and kt-soft-soft.dat, written by
# softpack-average; columns 1 delta_n, 2 kt_mean [N/m], 3 kt_stderr, 4 seeds) and out (.pdf:
# pdfcairo, 8.5 cm x 8.5 cm, one journal column; otherwise pngcairo, 1700 x 1700 px).
# Optional:
#   kt_a_solid kt_b_solid kt_c_solid [kt_delta_solid], the same with _soft
#       our Eq. 8 fit (data/<profile>/fit/<scene>.json, "tangential"). A scene's curve is drawn
#       only if its a, b and c are given and are not NaN: a null tangential fit is passed by
#       leaving the variables out (or as NaN). Eq. 8 is zero below the onset: kt_delta_<scene>,
#       else delta_<scene> (the normal fit's δ, as the paper does), else (-c/a)^(1/b).
#   delta_solid delta_soft                          our normal-law onsets (see above)
#   paper_kt_a_solid paper_kt_b_solid paper_kt_c_solid paper_kt_delta_solid (and _soft)
#       the paper's Table 2 and its δ from Table 1 (required): load the file of softpack-table --gnuplot.
#   log = 1    one logarithmic axis for everything, instead of the right axis (see below).
#
# The paper's kt, read in its printed unit N/m, is tiny (0.17 "N/m" at Δn = 0.5 for soft-solid:
# 0.14 mm of ht would give 24 µN, under 1e-5 of the Coulomb limit mu Fn = 3 N). Its unit is
# doubtful (docs/paper-in-one-page.md), so the default plot compares shapes: ours on the left
# axis, the paper's curves (dashed) on the right axis, both linear with the zeros aligned, the
# right axis scaled so that the larger of the paper's curves spans the same height as our data
# (the ratio is printed in the graph). The key says which axis a curve belongs to. With log=1,
# both share one log axis and the gap in magnitude is seen directly (zero and negative values
# of kt are then not drawn).

if (!exists("avg") || !exists("out")) {
  print "usage: gnuplot -e \"avg='data/<profile>/average'; out='fig6_kt.pdf|png'\" [-e \"kt_a_solid=..; kt_b_solid=..; kt_c_solid=..; kt_a_soft=..; kt_b_soft=..; kt_c_soft=..; delta_solid=..; delta_soft=..; log=1\"] figures/fig6_kt.gp"
  exit status 2
}
# A profile may measure one scene (normal.scenes): the other's file is then absent, and its
# points, fit and paper curve are not drawn.
file_solid = avg."/kt-soft-solid.dat"
file_soft = avg."/kt-soft-soft.dat"
readable(f) = system("test -r '".f."' && echo yes") eq "yes"
has_solid = readable(file_solid)
has_soft = readable(file_soft)
if (!has_solid && !has_soft) {
  print "fig6_kt.gp: cannot read ".file_solid." nor ".file_soft
  exit status 2
}
files = (has_solid ? file_solid." " : "").(has_soft ? file_soft : "")
if (!has_solid) { file_solid = "/dev/null" }
if (!has_soft) { file_soft = "/dev/null" }

# The paper's Table 2 with δ of Table 1: from experiments/published.yaml via softpack-table --gnuplot.
# (of the scenes measured: softpack-table writes those of the profile's scenes)
paper_vars = (has_solid ? "paper_kt_a_solid paper_kt_b_solid paper_kt_c_solid paper_kt_delta_solid " : "").(has_soft ? "paper_kt_a_soft paper_kt_b_soft paper_kt_c_soft paper_kt_delta_soft" : "")
do for [v in paper_vars] {
  if (!exists(v)) {
    print "fig6_kt.gp: ".v." is not set: load the published coefficients, -e \"load 'published.gp'\" (softpack-table --gnuplot, from experiments/published.yaml)"
    exit status 2
  }
}
if (!exists("log")) { log = 0 }

isnum(v) = (v == v)
onset(a, b, c) = (c < 0 && a > 0) ? (-c / a)**(1.0 / b) : 0.0
have_solid = exists("kt_a_solid") && exists("kt_b_solid") && exists("kt_c_solid")
if (have_solid) { have_solid = isnum(kt_a_solid) && isnum(kt_b_solid) && isnum(kt_c_solid) }
have_soft = exists("kt_a_soft") && exists("kt_b_soft") && exists("kt_c_soft")
if (have_soft) { have_soft = isnum(kt_a_soft) && isnum(kt_b_soft) && isnum(kt_c_soft) }
if (have_solid) {
  if (!exists("kt_delta_solid")) { kt_delta_solid = exists("delta_solid") ? delta_solid : NaN }
  if (!isnum(kt_delta_solid)) { kt_delta_solid = onset(kt_a_solid, kt_b_solid, kt_c_solid) }
} else { kt_a_solid = kt_b_solid = kt_c_solid = kt_delta_solid = NaN }
if (have_soft) {
  if (!exists("kt_delta_soft")) { kt_delta_soft = exists("delta_soft") ? delta_soft : NaN }
  if (!isnum(kt_delta_soft)) { kt_delta_soft = onset(kt_a_soft, kt_b_soft, kt_c_soft) }
} else { kt_a_soft = kt_b_soft = kt_c_soft = kt_delta_soft = NaN }

# Eq. 8: zero below the onset (not drawable on a log axis).
law(x, a, b, c, d) = (x < d) ? (log ? 1/0 : 0.0) : a * x**b + c
pos(y) = (log && y <= 0) ? 1/0 : y

if (out[strlen(out)-3:] eq ".pdf") {
  set terminal pdfcairo size 8.5cm,8.5cm font "Helvetica,8" linewidth 1.2
  ps = 0.45
} else {
  set terminal pngcairo size 1700,1700 font "Helvetica,27" linewidth 4
  ps = 2.2
}
set output out

# Ranges: x from 0 (the paper's onsets are at 0.065 and 0.148) to the largest Δn measured;
# y over our means with their error bars.
xmax = -1e300; ytop = -1e300; ybot = 1e300
do for [f in files] {
  stats f using 1 nooutput
  if (STATS_max > xmax) { xmax = STATS_max }
  stats f using ($2 + $3) nooutput
  if (STATS_max > ytop) { ytop = STATS_max }
  stats f using ($2 - $3) nooutput
  if (STATS_min < ybot) { ybot = STATS_min }
}
if (ybot > 0) { ybot = 0 }
if (ytop <= 0) { ytop = 1 }
ytop = 1.1 * ytop
ybot = 1.1 * ybot - 0.02 * ytop
paper_top = has_solid ? law(xmax, paper_kt_a_solid, paper_kt_b_solid, paper_kt_c_solid, paper_kt_delta_solid) : -1e300
t = has_soft ? law(xmax, paper_kt_a_soft, paper_kt_b_soft, paper_kt_c_soft, paper_kt_delta_soft) : -1e300
if (t > paper_top) { paper_top = t }
ratio = 1.1 * paper_top / ytop

set xrange [0 : xmax * 1.02]
set xlabel "normal deformation {/Symbol D}_n = h_n / R_s"
set grid xtics ytics lc rgb "#dddddd" lw 0.5
set mxtics 2
set bars small
set samples 600
set key below center vertical maxrows 3 reverse Left samplen 2.2 spacing 1.0 width -5 nobox
c_sol = "#1f5fa8"
c_sft = "#c8400e"

if (log) {
  set logscale y
  set format y "10^{%L}"
  # smallest positive mean (stats fails on a file without one: check the largest first)
  lo = paper_top / 100.0
  do for [f in files] {
    stats f using 2 nooutput
    if (STATS_max > 0) { stats f using ($2 > 0 ? $2 : 1/0) nooutput; if (STATS_min < lo) { lo = STATS_min } }
  }
  set yrange [10.0**floor(log10(lo)) : 10.0**ceil(log10(ytop))]
  set ylabel "tangential spring constant k_t [N/m]"
  paper_axes = "x1y1"
  paper_note = ', "N/m" as printed'
} else {
  set yrange [ybot : ytop]
  set y2range [ybot * ratio : ytop * ratio]
  set ytics nomirror
  set y2tics
  set ylabel "k_t, ours [N/m]"
  set y2label "k_t, paper's Table 2 [\"N/m\" as printed]" tc rgb "#555555"
  set y2tics textcolor rgb "#555555"
  set xzeroaxis lt 1 lc rgb "#888888" lw 0.5
  paper_axes = "x1y2"
  paper_note = ", right axis"
  set label 1 sprintf("right axis = left axis / %.3g", 1.0 / ratio) at graph 0.03, 0.95 left tc rgb "#555555"
}

# (An unmeasured scene's entries have an empty title: no key entry, nothing drawn.)
shown(on, t) = on ? t : ""
plot file_solid using 1:(pos($2)):3 with yerrorbars pt 7 ps ps lc rgb c_sol title shown(has_solid, "soft-solid, ours ± s.e."), \
     (have_solid ? law(x, kt_a_solid, kt_b_solid, kt_c_solid, kt_delta_solid) : 1/0) with lines lc rgb c_sol lw 1.5 \
        title shown(has_solid, have_solid ? "soft-solid, our fit (Eq. 8)" : "soft-solid, our fit: none"), \
     (has_solid ? law(x, paper_kt_a_solid, paper_kt_b_solid, paper_kt_c_solid, paper_kt_delta_solid) : 1/0) axes @paper_axes \
        with lines lc rgb c_sol lw 1.5 dt (6,4) title shown(has_solid, "soft-solid, paper, Table 2".paper_note), \
     file_soft using 1:(pos($2)):3 with yerrorbars pt 5 ps ps lc rgb c_sft title shown(has_soft, "soft-soft, ours ± s.e."), \
     (have_soft ? law(x, kt_a_soft, kt_b_soft, kt_c_soft, kt_delta_soft) : 1/0) with lines lc rgb c_sft lw 1.5 \
        title shown(has_soft, have_soft ? "soft-soft, our fit (Eq. 8)" : "soft-soft, our fit: none"), \
     (has_soft ? law(x, paper_kt_a_soft, paper_kt_b_soft, paper_kt_c_soft, paper_kt_delta_soft) : 1/0) axes @paper_axes \
        with lines lc rgb c_sft lw 1.5 dt (6,4) title shown(has_soft, "soft-soft, paper, Table 2".paper_note)
