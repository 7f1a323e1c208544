#pragma once
// A Thyra ModelEvaluator over a ResidualModel: the adapter through which NOX's Newton solver
// and Stratimikos' linear solvers see impm's grid systems.

#include <Thyra_StateFuncModelEvaluatorBase.hpp>

#include "solver/ResidualModel.hpp"

namespace impm {

class MpmModelEvaluator : public Thyra::StateFuncModelEvaluatorBase<double> {
 public:
  using LOWSFactory = Thyra::LinearOpWithSolveFactoryBase<double>;

  MpmModelEvaluator(Teuchos::RCP<ResidualModel> model, Teuchos::RCP<const LOWSFactory> lows);

  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> get_x_space() const override;
  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> get_f_space() const override;
  Thyra::ModelEvaluatorBase::InArgs<double> getNominalValues() const override;
  Thyra::ModelEvaluatorBase::InArgs<double> createInArgs() const override;
  Teuchos::RCP<Thyra::LinearOpBase<double>> create_W_op() const override;
  Teuchos::RCP<const LOWSFactory> get_W_factory() const override;

 private:
  Thyra::ModelEvaluatorBase::OutArgs<double> createOutArgsImpl() const override;
  void evalModelImpl(const Thyra::ModelEvaluatorBase::InArgs<double>& in,
                     const Thyra::ModelEvaluatorBase::OutArgs<double>& out) const override;

  Teuchos::RCP<ResidualModel> model_;
  Teuchos::RCP<const LOWSFactory> lows_;
  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> space_;
  Thyra::ModelEvaluatorBase::InArgs<double> nominal_;
};

}  // namespace impm
