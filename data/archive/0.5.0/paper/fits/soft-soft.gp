# softpack-fit 0.5.0 (7e34783-dirty) of data/paper/averages/soft-soft.h5 (soft-soft): Eq. 7 and Eq. 8 coefficients for gnuplot
a_soft=13.913104226703886; b_soft=3.9594044031613844; c_soft=-0.026220751582360386; delta_soft=0.20503170122029793
kt_a_soft=1439.3021873838434; kt_b_soft=2.5077772981023685; kt_c_soft=-27.061530205231477; kt_delta_soft=0.20503170122029793
