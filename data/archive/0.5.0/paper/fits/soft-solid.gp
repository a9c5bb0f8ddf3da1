# softpack-fit 0.5.0 (7e34783-dirty) of data/paper/averages/soft-solid.h5 (soft-solid): Eq. 7 and Eq. 8 coefficients for gnuplot
a_solid=82.14463032751256; b_solid=2.7870286836293663; c_solid=-0.1482970138948414; delta_solid=0.10366625508002779
kt_a_solid=2237.66684943117; kt_b_solid=1.6376846787985238; kt_c_solid=-54.666327137342115; kt_delta_solid=0.10366625508002779
