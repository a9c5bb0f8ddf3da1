# A confined part of the probe (make many-body-report draws each; studies/coarse/probe_soft_soft.hpp,
# probe_body.hpp): the force on the body pressing the centre while walls confine it (a resolved
# soft-particle, or a grain or a wall), against its Δn, mean over the seeds with its standard
# error, and each form of the part's report.
# One figure per radius (`out` holds %s for the radius's name), one panel per confined run of the part.
#
#   gnuplot -e "load 'data/many-body/report/fifth-version-vars.gp'; out='fifth-%s.png'" figures/confined_soft.gp
#
# The part's variables file (probe-report writes it beside NAME.dat): data (the .dat), radii
# (their names, in the .dat's order), runs (the confined runs, NAME:KIND, in its order), forms
# (the forms' names, columns 6 on), and optionally body (what presses; a soft-particle if not
# given). data: blocks '# RADIUS RUN', radii then runs; columns 3
# delta_n, 4-5 F measured (mean, se) [N], then each form's F.

if (!exists("data") || !exists("out") || !exists("radii") || !exists("runs") || !exists("forms")) {
  print "usage: gnuplot -e \"load '.../NAME-vars.gp'; out='NAME-%s.pdf|png'\" figures/confined_soft.gp"
  exit status 2
}
if (system("test -r '".data."' && echo yes") ne "yes") {
  print "confined_soft.gp: cannot read ".data
  exit status 2
}
if (!exists("body")) body = "soft-particle"
n = words(runs)
rows = n > 12 ? 4 : 2  # two rows up to twelve runs, four beyond
columns = (n + rows - 1) / rows
if (out[strlen(out)-3:] eq ".pdf") {
  set terminal pdfcairo size (8 * columns)cm,(7 * rows)cm font "Helvetica,7" linewidth 1.2
} else {
  set terminal pngcairo size 800 * columns,700 * rows font "Helvetica,18" linewidth 2
}
set grid
set logscale y
set yrange [1e-4:10]
set xrange [0:0.42]
set key bottom right
set xlabel sprintf("{/Symbol D}n of the pressing %s", body)
set ylabel "F_n on it [N]"
colours = "#1f77b4 #d62728 #2ca02c #9467bd"
do for [radius = 1:words(radii)] {
  set output sprintf(out, word(radii, radius))
  set multiplot layout rows,columns
  do for [b = 1:n] {
    i = (radius - 1) * n + (b - 1)
    set title sprintf("%s (%s)", word(runs, b), word(radii, radius))
    plot data index i using 3:4:5 with yerrorbars pt 7 lc rgb "black" title "measured", \
         for [f = 1:words(forms)] '' index i using 3:(column(5 + f)) with lines lw 2 dt f lc rgb word(colours, f) title word(forms, f)
  }
  unset multiplot
}
