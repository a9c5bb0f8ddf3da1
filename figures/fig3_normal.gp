# Figure 3: the normal contact law Fn(Δn), Δn = hn/Rs, of the soft-solid and soft-soft contacts,
# against Hertz's law for one solid sphere of radius Rs on a wall (the paper's top curve).
#
#   gnuplot -e "avg='data/paper/average'; out='data/paper/figures/fig3_normal.pdf'" \
#           -e "a_solid=113.2; b_solid=4.41; c_solid=-0.052; delta_solid=0.173" \
#           -e "a_soft=30.1; b_soft=8.02; c_soft=-0.0197; delta_soft=0.401" figures/fig3_normal.gp
#
# Required: avg (the folder with normal-soft-solid.dat and normal-soft-soft.dat, written by
# softpack-average; columns 1 delta_n, 2 Fn_mean [N], 3 Fn_stderr [N]) and out (.pdf: pdfcairo,
# 8.5 cm x 8.5 cm, one journal column; otherwise pngcairo, 1700 x 1700 px, the same layout).
# Optional:
#   a_solid b_solid c_solid delta_solid, a_soft b_soft c_soft delta_soft
#       our Eq. 7 fit (data/<profile>/fit/<scene>.json, "normal"); a curve is drawn only if its
#       a, b and c are given and not NaN; delta defaults to (-c/a)^(1/b) (0 if c >= 0).
#   paper_a_solid paper_b_solid paper_c_solid paper_delta_solid (and _soft)
#       the paper's Table 1 (required): load the file of softpack-table --gnuplot.
#   Rs [m] = 0.016, E [Pa] = 5e5, nu = 0.3    Hertz's law of the solid sphere (paper §4).
#
# The y axis is logarithmic: Hertz's law reaches 33 N at Δn = 0.5 while the soft-soft law stays
# below 1 N, so on a linear axis the soft-soft curve lies on the x axis; the log axis shows all
# three laws, their onsets and the factor between them. Points whose mean force is below the
# axis floor (zero before the onset) are drawn as open triangles on the floor.

if (!exists("avg") || !exists("out")) {
  print "usage: gnuplot -e \"avg='data/<profile>/average'; out='fig3_normal.pdf|png'\" [-e \"a_solid=..; b_solid=..; c_solid=..; delta_solid=..; a_soft=..; b_soft=..; c_soft=..; delta_soft=..\"] figures/fig3_normal.gp"
  exit status 2
}
# A profile may measure one scene (normal.scenes): the other's file is then absent, and its
# points, fit and paper curve are not drawn.
file_solid = avg."/normal-soft-solid.dat"
file_soft = avg."/normal-soft-soft.dat"
readable(f) = system("test -r '".f."' && echo yes") eq "yes"
has_solid = readable(file_solid)
has_soft = readable(file_soft)
if (!has_solid && !has_soft) {
  print "fig3_normal.gp: cannot read ".file_solid." nor ".file_soft
  exit status 2
}
if (!has_solid) { file_solid = "/dev/null" }
if (!has_soft) { file_soft = "/dev/null" }

# The paper's Table 1: from experiments/published.yaml via softpack-table --gnuplot.
# (of the scenes measured: softpack-table writes those of the profile's scenes)
paper_vars = (has_solid ? "paper_a_solid paper_b_solid paper_c_solid paper_delta_solid " : "").(has_soft ? "paper_a_soft paper_b_soft paper_c_soft paper_delta_soft" : "")
do for [v in paper_vars] {
  if (!exists(v)) {
    print "fig3_normal.gp: ".v." is not set: load the published coefficients, -e \"load 'published.gp'\" (softpack-table --gnuplot, from experiments/published.yaml)"
    exit status 2
  }
}
if (!exists("Rs")) { Rs = 0.016 }
if (!exists("E")) { E = 5.0e5 }
if (!exists("nu")) { nu = 0.3 }

# Our fits: present only when a, b and c are given and are numbers (NaN counts as absent).
isnum(v) = (v == v)
have_solid = exists("a_solid") && exists("b_solid") && exists("c_solid")
if (have_solid) { have_solid = isnum(a_solid) && isnum(b_solid) && isnum(c_solid) }
have_soft = exists("a_soft") && exists("b_soft") && exists("c_soft")
if (have_soft) { have_soft = isnum(a_soft) && isnum(b_soft) && isnum(c_soft) }
onset(a, b, c) = (c < 0 && a > 0) ? (-c / a)**(1.0 / b) : 0.0
if (have_solid && !exists("delta_solid")) { delta_solid = onset(a_solid, b_solid, c_solid) }
if (have_soft && !exists("delta_soft")) { delta_soft = onset(a_soft, b_soft, c_soft) }
if (have_solid) { if (!isnum(delta_solid)) { delta_solid = onset(a_solid, b_solid, c_solid) } }
if (have_soft) { if (!isnum(delta_soft)) { delta_soft = onset(a_soft, b_soft, c_soft) } }
if (!have_solid) { a_solid = b_solid = c_solid = delta_solid = NaN }
if (!have_soft) { a_soft = b_soft = c_soft = delta_soft = NaN }

# Eq. 7 (zero below the onset; log axis: zero is not drawn) and Eq. 3-4 for one material.
law(x, a, b, c, d) = (x < d) ? 1/0 : ((a * x**b + c) > 0 ? a * x**b + c : 1/0)
D = 0.75 * 2.0 * (1.0 - nu**2) / E
hertz(x) = sqrt(Rs) * (x * Rs)**1.5 / D

if (out[strlen(out)-3:] eq ".pdf") {
  set terminal pdfcairo size 8.5cm,8.5cm font "Helvetica,8" linewidth 1
  ps = 0.45
} else {
  set terminal pngcairo size 1700,1700 font "Helvetica,27" linewidth 4
  ps = 2.2
}
set output out

# Axis: from the decade of the smallest positive mean force (at least 1e-5 N) to above Hertz.
# (stats fails on a file without a valid point: look at the largest force first)
ymin_solid = ymin_soft = 1e-4
if (has_solid) {
  stats file_solid using 2 nooutput
  if (STATS_max > 0) { stats file_solid using ($2 > 0 ? $2 : 1/0) nooutput; ymin_solid = STATS_min }
}
if (has_soft) {
  stats file_soft using 2 nooutput
  if (STATS_max > 0) { stats file_soft using ($2 > 0 ? $2 : 1/0) nooutput; ymin_soft = STATS_min }
}
stats (has_solid ? file_solid : file_soft) using 1 nooutput
xmax = STATS_max
ymin = (ymin_solid < ymin_soft ? ymin_solid : ymin_soft)
floor_exp = floor(log10(ymin))
if (floor_exp < -5) { floor_exp = -5 }
yfloor = 10.0**floor_exp
ytop = 10.0**ceil(log10(hertz(xmax)) + 0.3)

set logscale y
set format y "10^{%L}"
set xrange [0 : xmax * 1.02]
set yrange [yfloor : ytop]
set xlabel "normal deformation {/Symbol D}_n = h_n / R_s"
set ylabel "normal force F_n [N]"
set grid xtics ytics lc rgb "#dddddd" lw 0.5
set mxtics 2
set key below center vertical maxrows 4 reverse Left samplen 2.2 spacing 1.0 width -1 nobox
set bars small
set samples 600

c_sol = "#1f5fa8"
c_sft = "#c8400e"
c_hz = "#333333"

below(y) = (y < yfloor) ? yfloor : 1/0

# Key below the graph in two columns: soft-solid on the left, soft-soft on the right, so that
# it hides no curve (inside, it would cover Hertz's law or the onsets).
# (An unmeasured scene's entries have an empty title: no key entry, nothing drawn.)
shown(on, t) = on ? t : ""
plot hertz(x) with lines lc rgb c_hz lw 1.2 dt 3 title "Hertz, solid sphere of radius R_s", \
     file_solid using 1:($2 >= yfloor ? $2 : 1/0):3 with yerrorbars pt 7 ps ps lc rgb c_sol title shown(has_solid, "soft-solid, ours (mean ± s.e.)"), \
     (have_solid ? law(x, a_solid, b_solid, c_solid, delta_solid) : 1/0) with lines lc rgb c_sol lw 1.5 title shown(has_solid, have_solid ? "soft-solid, our fit (Eq. 7)" : "soft-solid, our fit: none"), \
     (has_solid ? law(x, paper_a_solid, paper_b_solid, paper_c_solid, paper_delta_solid) : 1/0) with lines lc rgb c_sol lw 1.5 dt (6,4) title shown(has_solid, "soft-solid, paper (Table 1)"), \
     file_soft using 1:(below($2)) with points pt 11 ps ps*0.9 lc rgb c_sft notitle, \
     file_solid using 1:(below($2)) with points pt 10 ps ps*1.7 lc rgb c_sol notitle, \
     NaN with points pt 10 ps ps*1.3 lc rgb "#777777" title "F_n below the axis (0 before onset)", \
     file_soft using 1:($2 >= yfloor ? $2 : 1/0):3 with yerrorbars pt 5 ps ps lc rgb c_sft title shown(has_soft, "soft-soft, ours (mean ± s.e.)"), \
     (have_soft ? law(x, a_soft, b_soft, c_soft, delta_soft) : 1/0) with lines lc rgb c_sft lw 1.5 title shown(has_soft, have_soft ? "soft-soft, our fit (Eq. 7)" : "soft-soft, our fit: none"), \
     (has_soft ? law(x, paper_a_soft, paper_b_soft, paper_c_soft, paper_delta_soft) : 1/0) with lines lc rgb c_sft lw 1.5 dt (6,4) title shown(has_soft, "soft-soft, paper (Table 1)")
