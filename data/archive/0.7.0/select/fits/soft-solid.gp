# softpack-fit 0.7.0 (d9f8835) of data/select/averages/soft-solid.h5 (soft-solid): Eq. 7 and Eq. 8 coefficients for gnuplot
a_solid=81.5110216056497; b_solid=2.6589067848021255; c_solid=-0.10994793669021626; delta_solid=0.08329098887922941
kt_a_solid=2031.2748773390792; kt_b_solid=1.4902355149572906; kt_c_solid=-50.0271231562951; kt_delta_solid=0.08329098887922941
