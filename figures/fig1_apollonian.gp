# Figure 1: a 2D Apollonian packing, circles true to scale and shaded by generation.
#
#   build/bin/softpack-apollonian --min-radius 1e-3 --out data/fig1/apollonian.dat
#   gnuplot -e "data='data/fig1/apollonian.dat'; out='fig1_apollonian.png'" figures/fig1_apollonian.gp
#   gnuplot -e "data='data/fig1/apollonian.dat'; out='fig1_apollonian.pdf'" figures/fig1_apollonian.gp
#
# The terminal follows the extension of `out` (.pdf: pdfcairo, 8.5 cm x 7 cm, one journal
# column; otherwise pngcairo, 1700 x 1400 px, the same layout at 500 dpi).
# Data columns: x y r generation; generation -1 is the bounding circle (outline only).

if (!exists("data") || !exists("out")) {
  print "usage: gnuplot -e \"data='FILE.dat'; out='FIG.png|FIG.pdf'\" figures/fig1_apollonian.gp"
  exit status 2
}

if (out[strlen(out)-3:] eq ".pdf") {
  set terminal pdfcairo size 8.5cm,7cm font "Helvetica,8" linewidth 1
} else {
  set terminal pngcairo size 1700,1400 font "Helvetica,32" linewidth 4
}
set output out

# Generations beyond 9 (only in the cusps of a --min-radius packing) share the last shade, so
# that the levels stay distinguishable.
stats data using 4 nooutput
gmax = (STATS_max < 9) ? STATS_max : 9
set cbrange [-0.5 : gmax + 0.5]
set palette maxcolors (gmax + 1)
# Pale (large, early) to dark (small, late), reversed magma: the fine structure stands out
# against the white voids, and the large circles do not swamp the page.
set palette defined (0 "#fcfdbf", 0.2 "#fe9f6d", 0.4 "#de4968", 0.6 "#8c2981", 0.8 "#3b0f70", 1 "#000004")
set colorbox vertical user origin 0.80, 0.15 size 0.035, 0.7

unset key
unset border
unset tics
set cbtics 1 scale 0
if (STATS_max > gmax) { set cbtics add ("≥".gmax gmax) }
set cblabel "generation" offset 0.5, 0
set size ratio -1
set margins 0, 0, 0, 0
set rmargin at screen 0.76
set xrange [-1.01 : 1.01]
set yrange [-1.01 : 1.01]

# Filled without outlines, which would turn the smallest circles into dark dots; a hairline
# only around circles above 1% of the outer radius, where the pale early generations meet the
# white voids. (Rows are selected through an undefined x: gnuplot skips those points.)
set style fill solid 1.0 noborder
plot data using ($4 >= 0 ? $1 : 1/0):2:3:4 with circles lc palette, \
     data using ($4 >= 0 && $3 > 0.01 ? $1 : 1/0):2:3 with circles fs empty border rgb "#505050" lw 0.25, \
     data using ($4 < 0 ? $1 : 1/0):2:3 with circles fs empty border rgb "black" lw 1
