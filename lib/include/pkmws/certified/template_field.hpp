// A ScalarField from a field written once as
//   template <class T> T eval(const T& x, const T& y) const
// for T = double, Interval, Grad<double>, Grad<Interval>, Jet<double>,
// Jet<Interval> (use only +, -, *, /, sqr, sqrt, abs, max(., double) on T),
// plus `CellState domain(const Box&) const` (where the field is C²) and
// optionally `bool excluded(const Box&) const` (ScalarField::excluded) and
// `Interval enclose_cheap(const Box&) const` (ScalarField::enclose_cheap) and
// `CellState side(const Box&, double) const` (ScalarField::side).
#pragma once

#include <utility>

#include "pkmws/certified/level_set.hpp"

namespace pkmws::certified {

template <class Impl>
class TemplateField final : public ScalarField {
 public:
  explicit TemplateField(Impl impl) : impl_(std::move(impl)) {}
  double value(geometry::Point p) const override { return impl_.template eval<double>(p.x, p.y); }
  Jet<double> jet(geometry::Point p) const override {
    return impl_.template eval<Jet<double>>(Jet<double>::variable_x(p.x), Jet<double>::variable_y(p.y));
  }
  Grad<double> grad(geometry::Point p) const override {
    return impl_.template eval<Grad<double>>(Grad<double>::variable_x(p.x), Grad<double>::variable_y(p.y));
  }
  Grad<Interval> grad(const geometry::Box& b) const override {
    using G = Grad<Interval>;
    return impl_.template eval<G>(G::variable_x(Interval(b.min.x, b.max.x)), G::variable_y(Interval(b.min.y, b.max.y)));
  }
  Interval enclose(const geometry::Box& b) const override {
    return impl_.template eval<Interval>(Interval(b.min.x, b.max.x), Interval(b.min.y, b.max.y));
  }
  /// `Interval enclose_cheap(const Box&) const` of Impl when it has one (see ScalarField).
  Interval enclose_cheap(const geometry::Box& b) const override {
    if constexpr (requires { impl_.enclose_cheap(b); }) {
      return impl_.enclose_cheap(b);
    } else {
      return Interval::whole();
    }
  }
  /// `CellState side(const Box&, double) const` of Impl when it has one (see ScalarField).
  CellState side(const geometry::Box& b, double level) const override {
    if constexpr (requires { impl_.side(b, level); }) {
      return impl_.side(b, level);
    } else {
      return CellState::undecided;
    }
  }
  Jet<Interval> jet(const geometry::Box& b) const override {
    using J = Jet<Interval>;
    return impl_.template eval<J>(J::variable_x(Interval(b.min.x, b.max.x)), J::variable_y(Interval(b.min.y, b.max.y)));
  }
  CellState domain(const geometry::Box& b) const override { return impl_.domain(b); }
  /// `bool excluded(const Box&) const` of Impl when it has one (see ScalarField).
  bool excluded(const geometry::Box& b) const override {
    if constexpr (requires { impl_.excluded(b); }) {
      return impl_.excluded(b);
    } else {
      return impl_.domain(b) == CellState::outside;
    }
  }
  const Impl& impl() const { return impl_; }

 private:
  Impl impl_;
};

}  // namespace pkmws::certified
