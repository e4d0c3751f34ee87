#pragma once
// Truncated power series whose coefficients are generated one order at a time, for the
// Taylor-series integrator (taylor.hpp).
//
// A polynomial right-hand side written once as a template over its scalar type (for
// instance a damping law's force_of_root) is evaluated on SeriesVariable leaves, each a
// view of the Taylor coefficients of one state component. The result is an expression
// of series nodes -- sums, differences, negations, products by and sums with doubles,
// and products of two series -- built once, with the structure of the formula as its
// type, so evaluating it inlines into straight-line code (no tape, no dispatch).
//
// update(k) computes coefficient k of a node from coefficients 0..k of its operands;
// it must be called for k = 0, 1, 2, ... in turn, after coefficient k of every leaf is
// set. A product is the only node with coefficients of its own (Cauchy product,
// c_k = sum_{j <= k} a_j b_{k-j}: O(k) per order, the terms that do not involve the
// operands' coefficient k summed before it is computed); the linear nodes read through
// to their operands. So the Taylor coefficients of y' = f(y) follow by the recurrence
//   y_{k+1} = f(y)_k / (k + 1),
// with O(p^2) work for order p per product in f.
//
// The products' coefficients live in a SeriesStorage that the expression's owner binds the
// finished expression to (bind), not in the nodes: building the expression copies every
// operand into its parent, and nodes that carried their series_capacity + 1 coefficients
// made the setup of each Taylor run copy and zero kilobytes.
//
// derivative(a) is the series of da/ds (coefficient j is (j + 1) a_{j+1}): its update(k)
// needs coefficient k + 1 of the leaves, so it applies once the state's series is
// complete (the Taylor integrator's event functions, such as the rate of a force), and
// it loses one order: a node's `lost_orders` says how many (an expression over order-p
// leaves is known to order p - lost_orders).
#include <algorithm>
#include <array>
#include <concepts>
#include <type_traits>

namespace hertzdash {

/// Highest coefficient index a series stores (the Taylor integrator's largest order).
inline constexpr int series_capacity = 32;

/// A node of a series expression (the tag every node carries).
template <class E>
concept SeriesExpression = std::remove_cvref_t<E>::is_series_expression;

/// A leaf: the coefficients of one state component, owned by the integrator.
struct SeriesVariable {
  static constexpr bool is_series_expression = true;
  static constexpr int lost_orders = 0;
  static constexpr int products = 0;  ///< product nodes in the expression (storage it needs)
  const double* c;
  double operator[](int j) const { return c[j]; }
  void update(int) {}
  void bind(double*&) {}
};

namespace series_detail {

template <class A>
struct Scaled {  // s a
  static constexpr bool is_series_expression = true;
  static constexpr int lost_orders = A::lost_orders;
  static constexpr int products = A::products;
  double s;
  A a;
  double operator[](int j) const { return s * a[j]; }
  void update(int k) { a.update(k); }
  void bind(double*& next) { a.bind(next); }
};

template <class A>
struct Shifted {  // s + a: the constant enters coefficient 0 only
  static constexpr bool is_series_expression = true;
  static constexpr int lost_orders = A::lost_orders;
  static constexpr int products = A::products;
  double s;
  A a;
  double operator[](int j) const { return j == 0 ? s + a[0] : a[j]; }
  void update(int k) { a.update(k); }
  void bind(double*& next) { a.bind(next); }
};

/// a + b (sign +1: Sum) or a - b (sign -1: Difference), coefficient by coefficient.
template <class A, class B, int sign>
struct SignedSum {
  static constexpr bool is_series_expression = true;
  static constexpr int lost_orders = std::max(A::lost_orders, B::lost_orders);
  static constexpr int products = A::products + B::products;
  A a;
  B b;
  double operator[](int j) const { return sign > 0 ? a[j] + b[j] : a[j] - b[j]; }
  void update(int k) {
    a.update(k);
    b.update(k);
  }
  void bind(double*& next) {
    a.bind(next);
    b.bind(next);
  }
};
template <class A, class B> using Sum = SignedSum<A, B, 1>;
template <class A, class B> using Difference = SignedSum<A, B, -1>;

template <class A, class B>
struct Product {
  static constexpr bool is_series_expression = true;
  static constexpr int lost_orders = std::max(A::lost_orders, B::lost_orders);
  static constexpr int products = A::products + B::products + 1;
  A a;
  B b;
  double* c = nullptr;  ///< series_capacity + 1 coefficients in a SeriesStorage (bind)
  double operator[](int j) const { return c[j]; }
  void bind(double*& next) {
    a.bind(next);
    b.bind(next);
    c = next;
    next += series_capacity + 1;
  }
  // The terms of orders below k first: they do not wait for the operands' coefficient k,
  // so the processor overlaps them with the chain that computes it (two partial sums).
  void update(int k) {
    double even = 0, odd = 0;
    int j = 1;
    for (; j + 1 < k; j += 2) {
      even += a[j] * b[k - j];
      odd += a[j + 1] * b[k - j - 1];
    }
    if (j < k) even += a[j] * b[k - j];
    a.update(k);
    b.update(k);
    c[k] = k == 0 ? a[0] * b[0] : ((even + odd) + a[k] * b[0]) + a[0] * b[k];
  }
};

template <class A>
struct Derivative {  // da/ds
  static constexpr bool is_series_expression = true;
  static constexpr int lost_orders = A::lost_orders + 1;
  static constexpr int products = A::products;
  A a;
  double operator[](int j) const { return (j + 1) * a[j + 1]; }
  void update(int k) {
    if (k == 0) a.update(0);
    a.update(k + 1);
  }
  void bind(double*& next) { a.bind(next); }
};

template <class E>
using Node = std::remove_cvref_t<E>;

template <class E>
inline constexpr bool is_scaled = false;
template <class A>
inline constexpr bool is_scaled<Scaled<A>> = true;

}  // namespace series_detail

/// The coefficients of every product node of some series expressions, which bind points
/// at their own slots (in the order given). Not zeroed: update(k) writes coefficient k of
/// a product before anything reads it. The expressions must not outlive the storage, and
/// a copy of a bound expression shares its slots.
template <int Products>
struct SeriesStorage {
  std::array<double, (series_capacity + 1) * Products> slots;
  template <SeriesExpression... E>
    requires((std::remove_cvref_t<E>::products + ... + 0) <= Products)
  void bind(E&... e) {
    double* next = slots.data();
    (e.bind(next), ...);
  }
};

/// The storage the product nodes of the given expression types need.
template <class... E>
inline constexpr int series_products = (std::remove_cvref_t<E>::products + ... + 0);

/// The series of da/ds (see above: for complete leaves only; one order lost).
template <SeriesExpression A>
auto derivative(A&& a) {
  return series_detail::Derivative<series_detail::Node<A>>{a};
}

template <SeriesExpression A, SeriesExpression B>
auto operator+(A&& a, B&& b) {
  return series_detail::Sum<series_detail::Node<A>, series_detail::Node<B>>{a, b};
}
template <SeriesExpression A, SeriesExpression B>
auto operator-(A&& a, B&& b) {
  return series_detail::Difference<series_detail::Node<A>, series_detail::Node<B>>{a, b};
}
template <SeriesExpression A, SeriesExpression B>
auto operator*(A&& a, B&& b) {
  return series_detail::Product<series_detail::Node<A>, series_detail::Node<B>>{a, b};
}
template <SeriesExpression A>
auto operator-(A&& a) {
  return -1.0 * a;
}
template <SeriesExpression A>
auto operator*(double s, A&& a) {
  if constexpr (series_detail::is_scaled<series_detail::Node<A>>) {
    return series_detail::Node<A>{s * a.s, a.a};  // one product by a constant, not two in a row
  } else {
    return series_detail::Scaled<series_detail::Node<A>>{s, a};
  }
}
template <SeriesExpression A>
auto operator*(A&& a, double s) {
  return s * a;
}
template <SeriesExpression A>
auto operator/(A&& a, double s) {
  return (1.0 / s) * a;
}
template <SeriesExpression A>
auto operator+(double s, A&& a) {
  return series_detail::Shifted<series_detail::Node<A>>{s, a};
}
template <SeriesExpression A>
auto operator+(A&& a, double s) {
  return series_detail::Shifted<series_detail::Node<A>>{s, a};
}
template <SeriesExpression A>
auto operator-(double s, A&& a) {
  return s + (-1.0 * a);
}
template <SeriesExpression A>
auto operator-(A&& a, double s) {
  return series_detail::Shifted<series_detail::Node<A>>{-s, a};
}

}  // namespace hertzdash
