#include "solver/ModelEvaluator.hpp"

#include <Thyra_TpetraThyraWrappers.hpp>
#include <Thyra_VectorStdOps.hpp>

#include "core/StopRequest.hpp"

namespace impm {

using MEB = Thyra::ModelEvaluatorBase;
using Extract = Thyra::TpetraOperatorVectorExtraction<double, LO, GO, Node>;

MpmModelEvaluator::MpmModelEvaluator(Teuchos::RCP<ResidualModel> model,
                                     Teuchos::RCP<const LOWSFactory> lows)
    : model_(std::move(model)), lows_(std::move(lows)) {
  space_ = Thyra::createVectorSpace<double, LO, GO, Node>(model_->unknownMap());
  MEB::InArgsSetup<double> in;
  in.setModelEvalDescription("impm grid system");
  in.setSupports(MEB::IN_ARG_x);
  nominal_ = in;
  auto x0 = Thyra::createMember(space_);
  Thyra::V_S(x0.ptr(), 0.0);
  nominal_.set_x(x0);
}

Teuchos::RCP<const Thyra::VectorSpaceBase<double>> MpmModelEvaluator::get_x_space() const {
  return space_;
}

Teuchos::RCP<const Thyra::VectorSpaceBase<double>> MpmModelEvaluator::get_f_space() const {
  return space_;
}

MEB::InArgs<double> MpmModelEvaluator::getNominalValues() const {
  return nominal_;
}

MEB::InArgs<double> MpmModelEvaluator::createInArgs() const {
  MEB::InArgsSetup<double> in;
  in.setModelEvalDescription("impm grid system");
  in.setSupports(MEB::IN_ARG_x);
  return std::move(in);
}

MEB::OutArgs<double> MpmModelEvaluator::createOutArgsImpl() const {
  MEB::OutArgsSetup<double> out;
  out.setModelEvalDescription("impm grid system");
  out.setSupports(MEB::OUT_ARG_f);
  out.setSupports(MEB::OUT_ARG_W_op);
  return std::move(out);
}

Teuchos::RCP<Thyra::LinearOpBase<double>> MpmModelEvaluator::create_W_op() const {
  Teuchos::RCP<Tpetra::Operator<double, LO, GO, Node>> op = model_->createJacobian();
  return Thyra::createLinearOp<double, LO, GO, Node>(op, space_, space_);
}

Teuchos::RCP<const MpmModelEvaluator::LOWSFactory> MpmModelEvaluator::get_W_factory() const {
  return lows_;
}

void MpmModelEvaluator::evalModelImpl(const MEB::InArgs<double>& in,
                                      const MEB::OutArgs<double>& out) const {
  // Every evaluation is collective, so every rank agrees here to abandon the step.
  if (stopAgreed(*model_->unknownMap()->getComm()))
    throw StopRequest();
  auto x = Extract::getConstTpetraVector(in.get_x());
  Teuchos::RCP<Vector> f;
  if (out.get_f() != Teuchos::null)
    f = Extract::getTpetraVector(out.get_f());
  Teuchos::RCP<CrsMatrix> W;
  if (out.get_W_op() != Teuchos::null)
    W = Teuchos::rcp_dynamic_cast<CrsMatrix>(Extract::getTpetraOperator(out.get_W_op()), true);
  model_->evaluate(*x, f.get(), W.get());
}

}  // namespace impm
