# softpack-fit 0.7.0 (7a9968e) of data/paper/averages/soft-solid.h5 (soft-solid): Eq. 7 and Eq. 8 coefficients for gnuplot
a_solid=82.24827391420625; b_solid=2.6732799481565124; c_solid=-0.13099886689945123; delta_solid=0.08982522873599089
kt_a_solid=2823.7325312158837; kt_b_solid=1.7952349823265643; kt_c_solid=-37.31879651822172; kt_delta_solid=0.08982522873599089
