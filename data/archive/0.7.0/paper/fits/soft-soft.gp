# softpack-fit 0.7.0 (7a9968e) of data/paper/averages/soft-soft.h5 (soft-soft): Eq. 7 and Eq. 8 coefficients for gnuplot
a_soft=14.603497525746537; b_soft=3.611565815723558; c_soft=-0.0222503274021159; delta_soft=0.16594820129716495
kt_a_soft=2108.644104048168; kt_b_soft=2.7402218581663225; kt_c_soft=-15.365794334416298; kt_delta_soft=0.16594820129716495
