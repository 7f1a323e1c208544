// assembly/DomainDistortion: |D| |D^-1| / Dim of D = R R0^-1 is 1 for a scaled and turned
// domain, (s + 1/s) / 2 for stretches in the ratio s, 3 for the shear [[1, 2], [0, 1]].

#include <gtest/gtest.h>

#include <cmath>

#include <Teuchos_DefaultComm.hpp>

#include "assembly/DomainDistortion.hpp"

namespace impm {
namespace {

TEST(DomainDistortion, MeasuresStretchAndShearNotScaleOrTurn) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  ParticleSet<2> ps{3};
  auto R = Kokkos::create_mirror_view(ps.domain);
  auto R0 = Kokkos::create_mirror_view(ps.domain0);
  auto id = Kokkos::create_mirror_view(ps.id);
  const double c = std::cos(0.5), s = std::sin(0.5);
  const double D[3][2][2] = {{{1.5 * c, -1.5 * s}, {1.5 * s, 1.5 * c}},  // turned, scaled
                             {{4.0, 0.0}, {0.0, 1.0}},                   // stretched 4 : 1
                             {{1.0, 2.0}, {0.0, 1.0}}};                  // sheared
  for (int p = 0; p < 3; ++p) {
    id(p) = 10 + p;
    const double r0[2][2] = {{0.1, 0.02}, {0.0, 0.05}};  // a parallelogram to start from
    for (int a = 0; a < 2; ++a)
      for (int k = 0; k < 2; ++k) {
        R0(p, a, k) = r0[a][k];
        R(p, a, k) = D[p][a][0] * r0[0][k] + D[p][a][1] * r0[1][k];
      }
  }
  Kokkos::deep_copy(ps.domain, R), Kokkos::deep_copy(ps.domain0, R0), Kokkos::deep_copy(ps.id, id);
  const auto d = domainDistortion(ps, *comm);
  EXPECT_NEAR(d.worst, 3.0, 1e-13);
  EXPECT_EQ(d.particle, 12);
  EXPECT_NEAR(d.smallestJ, 1.0, 1e-13);
  // Without the shear, the stretch: (4 + 1/4) / 2.
  ParticleSet<2> two{2};
  Kokkos::deep_copy(two.domain, Kokkos::subview(ps.domain, Kokkos::make_pair(0, 2), Kokkos::ALL(),
                                                Kokkos::ALL()));
  Kokkos::deep_copy(two.domain0, Kokkos::subview(ps.domain0, Kokkos::make_pair(0, 2), Kokkos::ALL(),
                                                 Kokkos::ALL()));
  Kokkos::deep_copy(two.id, Kokkos::subview(ps.id, Kokkos::make_pair(0, 2)));
  const auto e = domainDistortion(two, *comm);
  EXPECT_NEAR(e.worst, 2.125, 1e-13);
  EXPECT_EQ(e.particle, 11);
  EXPECT_NEAR(e.smallestJ, 2.25, 1e-13);
}

}  // namespace
}  // namespace impm
