// material: the 1-D linear law through the first-Piola interface, position-dependent
// parameters, and clear errors for inadmissible values.

#include <gtest/gtest.h>

#include "core/Errors.hpp"
#include "core/Parameters.hpp"
#include "material/MaterialFactory.hpp"

namespace impm {
namespace {

std::shared_ptr<Material<1>> linear(const std::string& E) {
  Teuchos::ParameterList p;
  p.set("Model", std::string("linear"));
  p.set("E", E);
  validateParameters(p, materialValidParameters());
  return createMaterial<1>("m", p);
}

ParticleSet<1> particlesAt(const std::vector<double>& X) {
  ParticleSet<1> ps(X.size());
  auto h = Kokkos::create_mirror_view(ps.X);
  for (std::size_t p = 0; p < X.size(); ++p)
    h(p, 0) = X[p];
  Kokkos::deep_copy(ps.X, h);
  return ps;
}

TEST(LinearElastic1D, StressAndTangentFromF) {
  auto m = linear("2 + x");
  auto ps = particlesAt({0.0, 0.5, 1.0});
  m->initialize(ps, 0);
  ParticleSet<1>::Tensors F("F", 3), P("P", 3);
  Material<1>::Tangents A("A", 3);
  auto Fh = Kokkos::create_mirror_view(F);
  Fh(0, 0, 0) = 1.0, Fh(1, 0, 0) = 1.1, Fh(2, 0, 0) = 0.8;
  Kokkos::deep_copy(F, Fh);
  m->firstPiola(ps, F, 0, P, A);
  auto Ph = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), P);
  auto Ah = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), A);
  EXPECT_DOUBLE_EQ(Ph(0, 0, 0), 0.0);
  EXPECT_NEAR(Ph(1, 0, 0), 2.5 * 0.1, 1e-15);
  EXPECT_NEAR(Ph(2, 0, 0), 3.0 * -0.2, 1e-15);
  EXPECT_DOUBLE_EQ(Ah(1, 0, 0, 0, 0), 2.5);
  EXPECT_DOUBLE_EQ(m->maxModulus(ps, 0), 3.0);
}

TEST(LinearElastic1D, OnlyItsOwnParticles) {
  auto m = linear("5");
  auto ps = particlesAt({0.0, 1.0});
  auto mat = Kokkos::create_mirror_view(ps.material);
  mat(1) = 1;
  Kokkos::deep_copy(ps.material, mat);
  m->initialize(ps, 0);
  ParticleSet<1>::Tensors F("F", 2), P("P", 2);
  Material<1>::Tangents A("A", 2);
  Kokkos::deep_copy(F, 2.0);
  Kokkos::deep_copy(P, -7.0);
  m->firstPiola(ps, F, 0, P, A);
  auto Ph = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), P);
  EXPECT_DOUBLE_EQ(Ph(0, 0, 0), 5.0);
  EXPECT_DOUBLE_EQ(Ph(1, 0, 0), -7.0);
}

TEST(LinearElastic1D, NonPositiveModulusAtAParticleNamesThePath) {
  auto m = linear("1 - 2*x");
  auto ps = particlesAt({0.25, 0.75});
  try {
    m->initialize(ps, 0);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.path(), "Materials/m/E");
    EXPECT_NE(std::string(e.what()).find("at x = 0.75"), std::string::npos) << e.what();
  }
}

TEST(MaterialFactory, ModelOfAnotherDimensionIsRejected) {
  Teuchos::ParameterList p;
  p.set("Model", std::string("linear"));
  p.set("E", 1.0);
  validateParameters(p, materialValidParameters());
  EXPECT_THROW(createMaterial<2>("m", p), InputError);
}

}  // namespace
}  // namespace impm
