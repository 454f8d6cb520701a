// MOMA test fixtures ([Vasilic]): configuration M1 built in code, the model of a
// loaded file, sampled reachable points.
#pragma once

#include <cmath>
#include <filesystem>
#include <numbers>
#include <random>
#include <vector>

#include "pkmws/io/mechanism_file.hpp"
#include "mechanisms/moma/moma.hpp"
#include "support/fixtures.hpp"

namespace pkmws::test::moma {

/// The bundled MOMA configurations (datasets/moma_*.json), sorted.
// The configurations of the program of building (moma_m<k>_..., not the derived criteria files).
inline std::vector<std::filesystem::path> moma_datasets() { return dataset_files("moma_m"); }

inline const mechanisms::Moma& as_moma(const io::MechanismFile& f) { return dynamic_cast<const mechanisms::Moma&>(*f.model); }

// M1 of [Vasilic] §4.1 built in code: guides at x = -+100 pointing down
// (alpha = 3pi/2 + gamma), stroke [0, 200], rods l.
inline mechanisms::Moma m1(double l = 250.0, double gamma_deg = 0.0, double stroke_max = 200.0) {
  using mechanisms::MomaLeg;
  const double a = 1.5 * std::numbers::pi + gamma_deg * std::numbers::pi / 180.0;
  return mechanisms::Moma({MomaLeg{{-100, 0}, a, 0, stroke_max, l, -1}, MomaLeg{{100, 0}, a, 0, stroke_max, l, -1}});
}

inline double distance(geometry::Point a, geometry::Point b) { return std::hypot(a.x - b.x, a.y - b.y); }

// Points in the workspace's bounding box that the file's branches reach.
inline std::vector<geometry::Point> reachable_samples(const mechanisms::Moma& m, std::mt19937& rng, int count) {
  const auto box = m.workspace().bbox();
  std::uniform_real_distribution<double> x(box.min.x, box.max.x), y(box.min.y, box.max.y);
  std::vector<geometry::Point> out;
  for (int k = 0; k < 200 * count && static_cast<int>(out.size()) < count; ++k) {
    const geometry::Point p{x(rng), y(rng)};
    if (m.reachable({p.x, p.y, 0})) out.push_back(p);
  }
  return out;
}

}  // namespace pkmws::test::moma
