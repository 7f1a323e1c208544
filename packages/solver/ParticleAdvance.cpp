#include "solver/ParticleAdvance.hpp"

#include "assembly/CornerMotion.hpp"
#include "assembly/ParticleUpdate.hpp"
#include "core/Timers.hpp"

namespace impm {

namespace {

// The step's F and stress committed to the particles; returns the trial state (du imported).
template <int Dim>
typename GridSystem<Dim>::Trial deform(GridSystem<Dim>& system, const Vector& du,
                                       Kinematics kinematics, ParticleSet<Dim>& particles) {
  auto trial = system.trialState(du);
  commitDeformation<Dim>(kinematics, trial.F, trial.P, particles);
  if (particles.has(kCompatibleFField))  // total-Lagrangian F-bar: the next step's g
    storeCompatibleF<Dim>(particles, trial.g);
  return trial;
}

template <int Dim>
void move(const GridSystem<Dim>& system, const Vector& duOverlap, Kinematics kinematics,
          ParticleSet<Dim>& particles) {
  const auto du = duOverlap.getLocalViewDevice(Tpetra::Access::ReadOnly);
  displaceParticles<Dim>(system.particleGridMap(), system.entryDofs(), du, particles);
  moveCorners<Dim>(kinematics, system.grid(), system.particleGridMap(), system.entryDofs(), du,
                   particles);
}

}  // namespace

template <int Dim>
void advanceParticles(GridSystem<Dim>& system, const Vector& du, Kinematics kinematics,
                      ParticleSet<Dim>& particles) {
  IMPM_TIMER("particle update");
  move(system, *deform(system, du, kinematics, particles).xOverlap, kinematics, particles);
}

template <int Dim>
void deformParticles(GridSystem<Dim>& system, const Vector& du, Kinematics kinematics,
                     ParticleSet<Dim>& particles) {
  IMPM_TIMER("particle update");
  deform(system, du, kinematics, particles);
}

template <int Dim>
void moveParticles(const GridSystem<Dim>& system, const Vector& du, Kinematics kinematics,
                   ParticleSet<Dim>& particles) {
  IMPM_TIMER("particle update");
  move(system, *system.toOverlap(du), kinematics, particles);
}

#define IMPM_INSTANTIATE(D)                                                                      \
  template void advanceParticles<D>(GridSystem<D>&, const Vector&, Kinematics, ParticleSet<D>&); \
  template void deformParticles<D>(GridSystem<D>&, const Vector&, Kinematics, ParticleSet<D>&);  \
  template void moveParticles<D>(const GridSystem<D>&, const Vector&, Kinematics, ParticleSet<D>&);
IMPM_INSTANTIATE(1)
IMPM_INSTANTIATE(2)
IMPM_INSTANTIATE(3)
#undef IMPM_INSTANTIATE

}  // namespace impm
