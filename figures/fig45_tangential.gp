# Figures 4 and 5: the tangential force Ft against the tangential deformation ht = π Rs α / 180
# at several normal deformations Δn; left the component parallel to the deformation, right the
# perpendicular one (paper §5: it averages to zero). scene=soft-solid gives Figure 4,
# scene=soft-soft Figure 5.
#
#   gnuplot -e "avg='data/paper/average'; scene='soft-solid'; out='data/paper/figures/fig4_tangential_soft_solid.pdf'" figures/fig45_tangential.gp
#   gnuplot -e "avg='data/paper/average'; scene='soft-soft'; out='data/paper/figures/fig5_tangential_soft_soft.pdf'" figures/fig45_tangential.gp
#
# Required: avg (the folder with tangential-<scene>.dat, written by softpack-average: one data
# block per Δn, columns 1 delta_n, 2 alpha_deg, 3 ht [m], 4 Ft_parallel_mean [N],
# 5 Ft_parallel_stderr, 6 Ft_perpendicular_mean, 7 Ft_perpendicular_stderr, 8 Fn_mean,
# 9 Fn_stderr), scene (soft-solid or soft-soft) and out (.pdf: pdfcairo, 17 cm x 7 cm, two
# journal columns; otherwise pngcairo, 2400 x 990 px, the same layout).
# Optional: funit = 1, 1e3 or 1e6 forces the force unit (N, mN, µN); by default the unit is the
# one that puts the largest |Ft| between 1 and 1000.
#
# The legend reads Δn from column 1 of each block. Both panels share the y range, so the
# perpendicular component is seen at the scale of the parallel one.

if (!exists("avg") || !exists("scene") || !exists("out")) {
  print "usage: gnuplot -e \"avg='data/<profile>/average'; scene='soft-solid|soft-soft'; out='FIG.pdf|FIG.png'\" figures/fig45_tangential.gp"
  exit status 2
}
if (scene ne "soft-solid" && scene ne "soft-soft") {
  print "fig45_tangential.gp: scene must be soft-solid or soft-soft, not '".scene."'"
  exit status 2
}
file = avg."/tangential-".scene.".dat"
if (system("test -r '".file."' && echo yes") ne "yes") {
  print "fig45_tangential.gp: cannot read ".file
  exit status 2
}

if (out[strlen(out)-3:] eq ".pdf") {
  set terminal pdfcairo size 17cm,7cm font "Helvetica,8" linewidth 1
  ps = 0.45
} else {
  set terminal pngcairo size 2400,990 font "Helvetica,22" linewidth 3
  ps = 1.6
}
set output out

# One block per Δn: its value for the legend.
stats file using 1 nooutput
nb = STATS_blocks
array dn[nb]
do for [k = 1:nb] {
  stats file index (k-1) using 1 nooutput
  dn[k] = STATS_min
}
# The largest |Ft| with its error bar, over both components: common y range and unit.
stats file using (abs($4) + $5) nooutput
fmax = STATS_max
stats file using (abs($6) + $7) nooutput
if (STATS_max > fmax) { fmax = STATS_max }
if (fmax <= 0) { fmax = 1e-6 }
if (!exists("funit")) { funit = (fmax >= 1.0) ? 1.0 : ((fmax >= 1e-3) ? 1e3 : 1e6) }
uname = (funit == 1.0) ? "N" : ((funit == 1e3) ? "mN" : "{/Symbol m}N")
ylim = 1.12 * fmax * funit
stats file using ($3 * 1000) nooutput
xlim = 1.08 * (abs(STATS_min) > abs(STATS_max) ? abs(STATS_min) : abs(STATS_max))

# Δn from low (dark) to high (light): trimmed plasma, so the last curve is still visible.
set palette defined (0 "#0d0887", 0.3 "#6a00a8", 0.55 "#b12a90", 0.8 "#e16462", 1 "#f2912a")
unset colorbox
frac(k) = (nb > 1) ? (k - 1.0) / (nb - 1.0) : 0.0
ptype(k) = word("7 5 9 11 13 4 6 8 10 12", (k - 1) % 10 + 1) + 0

set xrange [-xlim : xlim]
set yrange [-ylim : ylim]
set xlabel "tangential deformation h_t [mm]"
set grid xtics ytics lc rgb "#dddddd" lw 0.5
set xzeroaxis lt 1 lc rgb "#888888" lw 0.5
set yzeroaxis lt 1 lc rgb "#888888" lw 0.5
set bars small
set tics nomirror out scale 0.6
set border 3

set multiplot layout 1,2 margins 0.075, 0.975, 0.14, 0.92 spacing 0.075, 0
set title scene.": F_t parallel to the deformation" offset 0, -0.6
set ylabel "F_{t,∥} [".uname."]"
unset key
plot for [k = 1:nb] file index (k-1) using ($3 * 1000):($4 * funit):($5 * funit) \
     with yerrorlines lc palette frac frac(k) pt ptype(k) ps ps lw 1.2 notitle

set title scene.": F_t perpendicular to the deformation" offset 0, -0.6
set ylabel "F_{t,⊥} [".uname."]"
set key top center horizontal maxcols 4 reverse Left samplen 1.5 spacing 1.0 width 0.5 opaque box lc rgb "#bbbbbb" \
    title "mean ± s.e. over seeds"
plot for [k = 1:nb] file index (k-1) using ($3 * 1000):($6 * funit):($7 * funit) \
     with yerrorlines lc palette frac frac(k) pt ptype(k) ps ps lw 1.2 \
     title sprintf("{/Symbol D}_n = %.3g", dn[k])
unset multiplot
