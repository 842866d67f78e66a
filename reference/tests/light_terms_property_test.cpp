// The light terms' bounds held to float32 (SPEC 7: each term's bound is
// property-tested against float32 evaluations with legal perturbations).
// Each sample draws a configuration (the hard cases of SPEC 10 among them:
// the point on the light, range edges, grazing light, a scene 1e5 from the
// origin), bounds shaders/light_terms.glsl with FloatBound, and evaluates
// it in float32 with every operation and input moved as far as the
// precision table allows, at random (perturbed_float.h). No evaluation may
// leave the bound, and the largest found must reach a quarter of it: a bound
// four times wider than float32 can go would let bugs through. With one
// operation's allowance taken out of the table the bound must fail.
#include "reference/light_terms.h"
#include "reference/surface_inputs.h"
#include "reference/tests/perturbed_float.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <iostream>
#include <map>
#include <random>
#include <string>

namespace reference {
namespace {

using lighting::Vec3;
using perturbed::Perturbation;
using perturbed::Perturbed;
using terms::Vec3Of;

constexpr int kSamples = 100000;

// One configuration of a light term, exact: camera-relative positions, the
// inputs' errors the fragment stage may bring (reference/surface_inputs.h).
struct Configuration {
  std::string kind;
  Vec3 color, light, spotDirection, p, N;
  double invRangeSq = 1, a = 0, b = 1, mask = 1;
  double positionError = 0, normalError = 0;
};

Vec3 randomUnit(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  Vec3 v(g(rng), g(rng), g(rng));
  while (glm::length(v) < 1e-6) v = Vec3(g(rng), g(rng), g(rng));
  return glm::normalize(v);
}

Vec3 asFloats(const Vec3& v) { return Vec3(double(float(v.x)), double(float(v.y)), double(float(v.z))); }

// Drawn around the hard cases of SPEC 10, in turn. With `exactInputs` the
// fragment's position and normal are floats already (no input error), so
// that the operations' own allowances are all the bound holds.
Configuration draw(std::mt19937_64& rng, int sample, bool exactInputs) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Configuration c;
  const double range = 0.5 + 20.0 * unit(rng);
  c.invRangeSq = 1.0 / (range * range);
  c.color = Vec3(2.0 * unit(rng), 2.0 * unit(rng), 2.0 * unit(rng));
  Vec3 origin(0.0);  // the camera's offset from the scene's points
  c.light = Vec3(10.0 * unit(rng) - 5.0, 10.0 * unit(rng) - 5.0, 10.0 * unit(rng) - 5.0);
  const Vec3 direction = randomUnit(rng);
  double d = 0;
  switch (sample % 5) {
    case 0:  // the point on the light (d = 0) or a few millimetres off
      c.kind = "d = 0";
      d = unit(rng) < 0.5 ? 0.0 : 0.005 * unit(rng);
      break;
    case 1:  // a range edge
      c.kind = "range edge";
      d = range * (1.0 + 1e-3 * (2.0 * unit(rng) - 1.0));
      break;
    case 2:  // grazing: N nearly across L
      c.kind = "grazing";
      d = range * unit(rng);
      break;
    case 3:  // the scene 1e5 from the origin: camera-relative, as the GPU gets it
      c.kind = "1e5 from the origin";
      origin = Vec3(1e5, 0.0, -1e5);
      d = range * unit(rng);
      break;
    default:
      c.kind = "anywhere";
      d = 1.2 * range * unit(rng);
  }
  c.p = c.light + direction * d;
  c.N = randomUnit(rng);
  if (c.kind == "grazing") c.N = glm::normalize(glm::cross(direction, randomUnit(rng)) + direction * (1e-4 * unit(rng)));
  if (unit(rng) < 0.5) {  // a spot light
    const double outer = 0.2 + 2.8 * unit(rng), inner = outer * unit(rng);
    const double cosOuter = std::cos(outer / 2), cosInner = std::cos(inner / 2);
    c.a = 1.0 / std::max(cosInner - cosOuter, 0.001);
    c.b = -cosOuter * c.a;
    c.spotDirection = randomUnit(rng);
  } else {
    c.spotDirection = Vec3(0, -1, 0);
  }
  if (unit(rng) < 0.3) c.mask = unit(rng);
  // Camera-relative, rounded as the CPU rounds (in double, then to float on upload).
  const Vec3 camera = origin + Vec3(0.0, 10.0 * unit(rng), 0.0);
  c.light = (c.light + origin) - camera;
  c.p = (c.p + origin) - camera;
  if (exactInputs) {
    c.p = asFloats(c.p);
    c.N = asFloats(c.N);
    return c;
  }
  const SurfaceErrors inputs = inputErrorsOfMagnitude(glm::length(c.p) + 10.0);
  c.positionError = inputs.position;
  c.normalError = inputs.normal;
  return c;
}

template <class P>
Vec3Of<FloatBoundOf<P>> uploaded(const Vec3& v) {
  using F = FloatBoundOf<P>;
  return {F::uploaded(v.x), F::uploaded(v.y), F::uploaded(v.z)};
}

template <class P>
Vec3Of<FloatBoundOf<P>> inputWithin(const Vec3& v, double error) {
  using F = FloatBoundOf<P>;
  return {F::input(v.x, error), F::input(v.y, error), F::input(v.z, error)};
}

Vec3Of<Perturbed> uploadedFloat(const Vec3& v) { return {Perturbed(v.x), Perturbed(v.y), Perturbed(v.z)}; }

// A float within `error` of each component of v, drawn as the perturbations are.
Vec3Of<Perturbed> floatWithin(const Vec3& v, double error, Perturbation& p) {
  auto one = [&](double x) {
    const double target = x + p.fraction() * error;
    float f = float(target);
    if (std::abs(double(f) - x) > error) f = std::nextafter(f, float(x));
    return Perturbed::of(f);
  };
  return {one(v.x), one(v.y), one(v.z)};
}

template <class P>
Vec3Of<FloatBoundOf<P>> boundLocal(const Configuration& c) {
  using F = FloatBoundOf<P>;
  return terms::localRadiance(uploaded<P>(c.color), uploaded<P>(c.light), F::uploaded(c.invRangeSq),
                              uploaded<P>(c.spotDirection), F::uploaded(c.a), F::uploaded(c.b), F::uploaded(c.mask),
                              F(1.0), inputWithin<P>(c.p, c.positionError), inputWithin<P>(c.N, c.normalError));
}

Vec3Of<Perturbed> floatLocal(const Configuration& c, Perturbation& p) {
  return terms::localRadiance(uploadedFloat(c.color), uploadedFloat(c.light), Perturbed(c.invRangeSq),
                              uploadedFloat(c.spotDirection), Perturbed(c.a), Perturbed(c.b), Perturbed(c.mask),
                              Perturbed(1.0), floatWithin(c.p, c.positionError, p), floatWithin(c.N, c.normalError, p));
}

template <class P>
Vec3Of<FloatBoundOf<P>> boundDirectional(const Configuration& c) {
  using F = FloatBoundOf<P>;
  return terms::directionalRadiance(uploaded<P>(c.color), uploaded<P>(c.spotDirection), F::uploaded(c.mask),
                                    inputWithin<P>(c.N, c.normalError));
}

Vec3Of<Perturbed> floatDirectional(const Configuration& c, Perturbation& p) {
  return terms::directionalRadiance(uploadedFloat(c.color), uploadedFloat(c.spotDirection), Perturbed(c.mask),
                                    floatWithin(c.N, c.normalError, p));
}

struct Largest {
  double ratio = 0;  // the largest |float - exact| / bound found
  std::string where;
  int exceeded = 0;  // evaluations outside the bound
  std::map<std::string, double> ratioOfKind;  // the largest per kind of configuration
};

// Every sample's float evaluations (three per configuration: every error
// upwards, every error downwards, each its own way) against its bound.
template <class P, class BoundTerm, class FloatTerm>
Largest check(BoundTerm bound, FloatTerm evaluate, std::uint64_t seed, bool exactInputs) {
  std::mt19937_64 rng(seed);
  Perturbation perturbation(seed + 1);
  perturbed::current() = &perturbation;
  Largest largest;
  for (int s = 0; s < kSamples; ++s) {
    const Configuration c = draw(rng, s, exactInputs);
    const Vec3Of<FloatBoundOf<P>> b = bound(c);
    for (const int lean : {1, -1, 0}) {
      perturbation.lean(lean);
      const Vec3Of<Perturbed> f = evaluate(c, perturbation);
      const double errors[3] = {std::abs(double(f.x.v) - b.x.value), std::abs(double(f.y.v) - b.y.value),
                                std::abs(double(f.z.v) - b.z.value)};
      const double bounds[3] = {b.x.error, b.y.error, b.z.error};
      for (int k = 0; k < 3; ++k) {
        if (!(errors[k] <= bounds[k])) ++largest.exceeded;
        const double ratio = bounds[k] > 0 ? errors[k] / bounds[k] : (errors[k] > 0 ? INFINITY : 0.0);
        double& ofKind = largest.ratioOfKind[c.kind];
        ofKind = std::max(ofKind, ratio);
        if (ratio > largest.ratio) {
          largest.ratio = ratio;
          largest.where = c.kind + ", sample " + std::to_string(s);
        }
      }
    }
  }
  perturbed::current() = nullptr;
  return largest;
}

// The table with one operation's allowance taken out, for the tests that
// show a bound too small fails.
struct WithoutAddAllowance : Float32Precision {
  static constexpr double kAddUlps = 0;
};
struct WithoutMultiplyAllowance : Float32Precision {
  static constexpr double kMultiplyUlps = 0;
};

// Both families: fragment inputs with the errors reference/surface_inputs.h
// gives them, and exact inputs, where the operations alone make the error.
void expectWithinAndSharp(const Largest& found, const char* family) {
  EXPECT_EQ(found.exceeded, 0) << family << ": largest |float - exact| / bound " << found.ratio << " (" << found.where
                               << ")";
  EXPECT_LE(found.ratio, 1.0) << family;
  EXPECT_GE(found.ratio, 0.25) << family << ": the bound is more than 4 times what float32 reached (" << found.where
                               << ")";
  std::cout << "  " << family << ": largest |float - exact| / bound = " << found.ratio << " (" << found.where << ");";
  for (const auto& [kind, ratio] : found.ratioOfKind) std::cout << " " << kind << " " << ratio << ";";
  std::cout << "\n";
}

TEST(LightTermBounds, PointAndSpotTermStaysWithinItsBound) {
  expectWithinAndSharp(check<Float32Precision>(boundLocal<Float32Precision>, floatLocal, 20261206, false),
                       "inputs with their errors");
  expectWithinAndSharp(check<Float32Precision>(boundLocal<Float32Precision>, floatLocal, 20261208, true),
                       "exact inputs");
}

TEST(LightTermBounds, DirectionalTermStaysWithinItsBound) {
  expectWithinAndSharp(check<Float32Precision>(boundDirectional<Float32Precision>, floatDirectional, 20261207, false),
                       "inputs with their errors");
  expectWithinAndSharp(check<Float32Precision>(boundDirectional<Float32Precision>, floatDirectional, 20261209, true),
                       "exact inputs");
}

// The bound adds every operation's largest error; float32 evaluations line
// them up only in part, so taking one operation's allowance out shows where
// that operation matters: the dot products' additions and the products.
TEST(LightTermBounds, PointAndSpotBoundWithoutTheAdditionsAllowanceFails) {
  EXPECT_GT((check<WithoutAddAllowance>(boundLocal<WithoutAddAllowance>, floatLocal, 20261208, true).exceeded), 0);
}

TEST(LightTermBounds, PointAndSpotBoundWithoutTheProductsAllowanceFails) {
  EXPECT_GT((check<WithoutMultiplyAllowance>(boundLocal<WithoutMultiplyAllowance>, floatLocal, 20261208, true).exceeded),
            0);
}

TEST(LightTermBounds, DirectionalBoundWithoutTheAdditionsAllowanceFails) {
  EXPECT_GT((check<WithoutAddAllowance>(boundDirectional<WithoutAddAllowance>, floatDirectional, 20261209, true).exceeded),
            0);
}

TEST(LightTermBounds, DirectionalBoundWithoutTheProductsAllowanceFails) {
  EXPECT_GT((check<WithoutMultiplyAllowance>(boundDirectional<WithoutMultiplyAllowance>, floatDirectional, 20261209,
                                             true)
                 .exceeded),
            0);
}

}  // namespace
}  // namespace reference
