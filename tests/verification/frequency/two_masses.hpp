#pragma once
// The frequency tests' two masses on springs (k1 = 1000 ground to mass 1, k2 = 500 mass 1 to
// mass 2, m1 = 2, m2 = 1, along x; eigenvalues 250 and 1000, derivation in
// verification_frequency_test.cpp): its model data, up to the first *STEP.

namespace gapfem::test {

inline constexpr const char* kTwoMassesModel = R"(*NODE
1, 0., 0., 0.
2, 1., 0., 0.
*ELEMENT, TYPE=SPRING1, ELSET=K1
1, 1
*SPRING, ELSET=K1
1
1000.
*ELEMENT, TYPE=SPRING2, ELSET=K2
2, 1, 2
*SPRING, ELSET=K2
1, 1
500.
*ELEMENT, TYPE=MASS, ELSET=M1
3, 1
*MASS, ELSET=M1
2.
*ELEMENT, TYPE=MASS, ELSET=M2
4, 2
*MASS, ELSET=M2
1.
*BOUNDARY
1, 2, 3
2, 2, 3
)";

} // namespace gapfem::test
