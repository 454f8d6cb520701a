#include <cmath>
#include <cstdlib>
#include <iostream>
#include <numbers>

#include "cli.hpp"
#include "pkmws/geometry/inscribed.hpp"

namespace pkmws::cli {

double elapsed_ms(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

void print_json(const Json& j) { std::cout << j.dump(2) << "\n"; }

double parse_number(const std::string& text, const std::string& what) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(v)) {
    throw io::InputError(what + ": expected a number, got \"" + text + "\"");
  }
  return v;
}

geometry::Region workspace_of(const io::MechanismFile& file) {
  try {
    return file.model->workspace();
  } catch (const std::exception& e) {
    throw io::InputError(file.path + ": " + e.what());
  }
}

certified::CertifiedRegion workspace_enclosure_of(const io::MechanismFile& file) {
  try {
    return file.model->workspace_enclosure();
  } catch (const std::exception& e) {
    throw io::InputError(file.path + ": " + e.what());
  }
}

std::string area_unit(const io::MechanismFile& file) { return file.units + "²"; }

namespace {

Json point_json(geometry::Point p) { return Json::array({p.x, p.y}); }

Json box_json(const geometry::Box& b) {
  return Json{{"min", point_json(b.min)}, {"max", point_json(b.max)}};
}

double precision_for(const geometry::Box& b) { return 1e-5 * std::max(b.width(), b.height()); }

}  // namespace

mechanisms::Pose sample_pose(const io::MechanismFile& file, const geometry::Region& region) {
  // 3-DOF: the platform at the file's constant orientation (the workspace's).
  const double phi = file.model->orientation();
  const auto comps = region.components();
  if (comps.empty()) {
    const auto b = file.model->bounds();
    return {(b.min.x + b.max.x) / 2, (b.min.y + b.max.y) / 2, phi};
  }
  std::size_t k = 0;
  for (std::size_t i = 1; i < comps.size(); ++i) {
    if (comps[i].area > comps[k].area) k = i;
  }
  const auto& c = comps[k];
  // Candidates: the centroid, the centre of the largest inscribed circle, and
  // points around it; the first reachable, non-singular pose wins (a drawing at
  // a singular pose, e.g. DexTAR's centre, hides the mechanism's shape).
  const auto circle = geometry::largest_inscribed_circle(c, 1e-3 * std::sqrt(c.area));
  std::vector<geometry::Point> candidates{c.centroid, circle.center};
  for (int i = 0; i < 8; ++i) {
    const double a = i * std::numbers::pi / 4 + 0.3;
    candidates.push_back({circle.center.x + 0.5 * circle.radius * std::cos(a),
                          circle.center.y + 0.5 * circle.radius * std::sin(a)});
  }
  for (const auto& p : candidates) {
    if (!geometry::inside(c, p) || geometry::distance_to_boundary(c, p) < 0.05 * std::sqrt(c.area)) continue;
    const mechanisms::Pose pose{p.x, p.y, phi};
    try {
      const auto ev = file.model->evaluate(pose, {});
      if (!ev.empty() && ev.front().reachable && !ev.front().singular) return pose;
    } catch (const std::exception&) {
      // a mechanism without evaluate at this pose: try the next candidate
    }
  }
  return {circle.center.x, circle.center.y, phi};
}

Json region_report(const geometry::Region& region, double min_area) {
  Json comps = Json::array();
  double area = 0.0;
  for (const auto& c : region.components(min_area)) {
    const auto circle = geometry::largest_inscribed_circle(c, precision_for(c.bbox));
    comps.push_back(Json{{"area", c.area},
                         {"perimeter", c.perimeter},
                         {"holes", c.holes.size()},
                         {"bbox", box_json(c.bbox)},
                         {"centroid", point_json(c.centroid)},
                         {"inscribed_circle",
                          {{"center", point_json(circle.center)},
                           {"radius", circle.radius},
                           {"radius_upper", circle.radius_upper}}}});
    area += c.area;
  }
  return Json{{"area", area}, {"components", comps}, {"bbox", box_json(region.bbox())},
              {"boundary_curves", region.curve_count()}};
}

}  // namespace pkmws::cli
