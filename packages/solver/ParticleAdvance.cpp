#include "solver/ParticleAdvance.hpp"

#include "assembly/CornerMotion.hpp"
#include "assembly/ParticleUpdate.hpp"
#include "core/Timers.hpp"

namespace impm {

template <int Dim>
void advanceParticles(GridSystem<Dim>& system, const Vector& du, Kinematics kinematics,
                      ParticleSet<Dim>& particles) {
  IMPM_TIMER("particle update");
  const auto trial = system.trialState(du);
  const auto values = trial.xOverlap->getLocalViewDevice(Tpetra::Access::ReadOnly);
  updateParticles<Dim>(kinematics, system.particleGridMap(), system.entryDofs(), values, trial.F,
                       trial.P, particles);
  moveCorners<Dim>(kinematics, system.grid(), system.particleGridMap(), system.entryDofs(), values,
                   particles);
}

template void advanceParticles<1>(GridSystem<1>&, const Vector&, Kinematics, ParticleSet<1>&);
template void advanceParticles<2>(GridSystem<2>&, const Vector&, Kinematics, ParticleSet<2>&);

}  // namespace impm
