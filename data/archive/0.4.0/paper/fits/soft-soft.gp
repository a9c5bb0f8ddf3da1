# softpack-fit 0.4.0 (72edb76) of data/paper/averages/soft-soft.h5 (soft-soft): Eq. 7 and Eq. 8 coefficients for gnuplot
a_soft=57326.81334311427; b_soft=22.55681575135296; c_soft=-9.33872811600079e-06; delta_soft=0.3681886516743532
kt_a_soft=66418170.812940195; kt_b_soft=23.921360492457737; kt_c_soft=-0.0027675819257483706; kt_delta_soft=0.3681886516743532
