# softpack-fit 0.7.0 (d9f8835) of data/select/averages/soft-soft.h5 (soft-soft): Eq. 7 and Eq. 8 coefficients for gnuplot
a_soft=18.715524632073507; b_soft=3.9114692569846596; c_soft=-0.022602709381777535; delta_soft=0.1794643361531503
kt_a_soft=1506.062903717573; kt_b_soft=2.380335392992339; kt_c_soft=-25.238347406162298; kt_delta_soft=0.1794643361531503
