# The coarse-grain validation's figure (make coarse-grain draws it for every setting; studies/coarse/report.hpp): the axial
# stress sigma_zz and the lateral stress ratio K0 against the strain of the oedometric
# compression, the resolved medium (every grain of both decades) and the soft-particle one, mean
# over the seeds with their standard errors; unloading as a second block.
#
#   gnuplot -e "data='data/coarse-grain/report/reference/curves.dat'; out='coarse-grain.pdf'" figures/coarse_grain.gp
#
# data: columns 1 strain, 2 phase, 3-4 sigma resolved (mean, error), 5-6 sigma soft, 7-8 K0
# resolved, 9-10 K0 soft, 11-12 solid fraction, 13-16 Z, 17-18 soft - resolved, 19 agrees,
# 20-23 tau resolved and soft; blocks: loading, unloading, shear (column 1 the wall's displacement).

if (!exists("data") || !exists("out")) {
  print "usage: gnuplot -e \"data='.../curves.dat'; out='coarse-grain.pdf|png'\" figures/coarse_grain.gp"
  exit status 2
}
if (system("test -r '".data."' && echo yes") ne "yes") {
  print "coarse_grain.gp: cannot read ".data
  exit status 2
}
if (out[strlen(out)-3:] eq ".pdf") {
  set terminal pdfcairo size 24cm,7cm font "Helvetica,7" linewidth 1.2
} else {
  set terminal pngcairo size 3600,1050 font "Helvetica,22" linewidth 3
}
set output out
set multiplot layout 1,3
set grid
set key top left
set xlabel "axial strain"
set ylabel "{/Symbol s}_{zz} [Pa]"
plot data index 0 using 1:3:4 with yerrorlines lc rgb "#1f77b4" pt 7 ps 0.3 title "resolved", \
     data index 0 using 1:5:6 with yerrorlines lc rgb "#d62728" pt 5 ps 0.3 title "soft-particles", \
     data index 1 using 1:3:4 with yerrorlines lc rgb "#1f77b4" dt 2 pt 7 ps 0.3 title "resolved, unloading", \
     data index 1 using 1:5:6 with yerrorlines lc rgb "#d62728" dt 2 pt 5 ps 0.3 title "soft, unloading"
set ylabel "K_0 = {/Symbol s}_{lateral} / {/Symbol s}_{zz}"
set yrange [0:1]
plot data index 0 using 1:7:8 with yerrorlines lc rgb "#1f77b4" pt 7 ps 0.3 title "resolved", \
     data index 0 using 1:9:10 with yerrorlines lc rgb "#d62728" pt 5 ps 0.3 title "soft-particles"
# The platen shear (third block, when the study has one): tau on the top wall against its displacement.
set autoscale y
set xlabel "top wall displacement / H_0"
set ylabel "{/Symbol t} [Pa]"
has_shear = system("awk 'BEGIN{b=0} /^$/{e++} e>=4 && !/^#/ && NF>0 {b=1} END{print b}' '".data."'") + 0
if (has_shear) {
  plot data index 2 using 1:20:21 with yerrorlines lc rgb "#1f77b4" pt 7 ps 0.3 title "resolved", \
       data index 2 using 1:22:23 with yerrorlines lc rgb "#d62728" pt 5 ps 0.3 title "soft-particles"
} else {
  unset border; unset tics; unset xlabel; unset ylabel
  set label 1 "no platen shear in this setting" at graph 0.5, 0.5 center
  set xrange [0:1]; set yrange [0:1]
  plot -1 notitle
}
unset multiplot
