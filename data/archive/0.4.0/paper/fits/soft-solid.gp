# softpack-fit 0.4.0 (72edb76) of data/paper/averages/soft-solid.h5 (soft-solid): Eq. 7 and Eq. 8 coefficients for gnuplot
a_solid=154.3681250822357; b_solid=4.685715140591807; c_solid=-0.021164669019858858; delta_solid=0.14982728557927097
kt_a_solid=8437.26457672342; kt_b_solid=4.543788451638859; kt_c_solid=-1.514471734069947; kt_delta_solid=0.14982728557927097
