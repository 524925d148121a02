#pragma once
// A technique's parameter plumbing, written once. A technique whose parameters are the
// struct P (a reflect() per parameter_binder.h) derives WithParameters<P>, or a family
// base built on it (ShadowMapScreenTechnique<P>, PrefilteredTechnique<P>,
// SinglePassTechnique<P>). The base owns `parameters_`; configure() binds the validated
// `--set` values to it, lets the family base hand its shared passes their part
// (configureShared()) and then calls configured() for the technique's derived state, so
// a technique without derived state writes no configure code at all. The registration
// (TESTBED_REGISTER_TECHNIQUE, PluginRegistrar::add) declares the specs from `Parameters`.
#include "testbed/technique/parameter_binder.h"
#include "testbed/technique/technique.h"

namespace testbed {

template <class P, class Base = ShadowTechnique>
class WithParameters : public Base {
 public:
  using Parameters = P;
  using Base::Base;

  void configure(const ParameterSet& values) final {
    bindParameters(values, parameters_);
    configureShared();
    configured();
  }

 protected:
  // For family bases: their shared passes take their part of `parameters_`.
  virtual void configureShared() {}
  // For techniques: what derives from `parameters_` (a format, a flag).
  virtual void configured() {}

  P parameters_{};
};

}  // namespace testbed
