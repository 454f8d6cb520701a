// `bodies` (docs/format.md (bodies)), strict: every field validated, unknown fields are errors.
//
// moma:     platform_joint {radius, min_link_angle_deg?}, rods [{radius} × 2],
//           slider_blocks [{length, width} × 2], housings [{extent [from, to], width} × 2],
//           obstacles [{name, polygon [[x, y], ...]}], allowed_contacts [[name, name], ...]
// five_bar: platform_joint, proximal [{radius} × 2], distal [{radius} × 2], obstacles, allowed_contacts
// Every group is optional. Lengths in the file's unit, angles in degrees.
#include "io/load_bodies.hpp"

#include <cmath>
#include <numbers>
#include <set>
#include <stdexcept>

namespace pkmws::io::detail {

namespace {

using bodies::Part;
using bodies::PartKind;
using geometry::Point;

constexpr double max_length = 1e15;

int orient(Point a, Point b, Point c) {
  const double v = cross(b - a, c - a);
  return v > 0 ? 1 : (v < 0 ? -1 : 0);
}

bool proper_or_touching(Point a, Point b, Point c, Point d) {
  const int o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  auto on = [](Point p, Point s, Point t) {
    return std::min(s.x, t.x) <= p.x && p.x <= std::max(s.x, t.x) && std::min(s.y, t.y) <= p.y &&
           p.y <= std::max(s.y, t.y);
  };
  return (o1 == 0 && on(c, a, b)) || (o2 == 0 && on(d, a, b)) || (o3 == 0 && on(a, c, d)) || (o4 == 0 && on(b, c, d));
}

std::vector<Point> read_polygon(JsonReader& r) {
  const auto& v = r.raw("polygon");
  if (!v.is_array() || v.size() < 3) r.fail("polygon", "expected at least 3 points [x, y]");
  const auto pts = r.points("polygon", v.size());
  double area2 = 0.0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Point a = pts[i], b = pts[(i + 1) % pts.size()];
    if (!(std::abs(a.x) <= max_length && std::abs(a.y) <= max_length)) {
      r.fail("polygon", "coordinates must not exceed 1e15 in magnitude");
    }
    area2 += cross(a, b);
  }
  if (!(std::abs(area2) > 0.0)) r.fail("polygon", "must have a positive area");
  const std::size_t n = pts.size();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      if (j == i + 1 || (i == 0 && j == n - 1)) continue;  // adjacent edges
      if (proper_or_touching(pts[i], pts[(i + 1) % n], pts[j], pts[(j + 1) % n])) {
        r.fail("polygon", "must be a simple polygon (edges " + std::to_string(i) + " and " + std::to_string(j) +
                              " meet)");
      }
    }
  }
  return pts;
}


}  // namespace

double part_length(JsonReader& r, const std::string& key, bool positive) {
  const double v = positive ? r.positive(key) : r.non_negative(key);
  if (!(v <= max_length)) r.fail(key, "magnitude must not exceed 1e15");
  return v;
}

Part leg_part(std::string name, PartKind kind, int leg) {
  Part p;
  p.name = std::move(name);
  p.kind = kind;
  p.leg = leg;
  return p;
}


void read_capsules(JsonReader& bodies, const std::string& key, const std::string& stem, bool proximal,
                   bodies::BodyModel& model) {
  if (!bodies.has(key)) return;
  auto items = bodies.objects(key, 2);
  for (int i = 0; i < 2; ++i) {
    auto& it = items[static_cast<std::size_t>(i)];
    it.declare_fields({"radius"});
    Part part = leg_part(stem + std::to_string(i + 1), PartKind::link, i);
    part.proximal = proximal;
    part.radius = part_length(it, "radius", false);
    it.finish();
    model.parts.push_back(part);
  }
}

std::shared_ptr<const bodies::BodyRig> load_bodies(JsonReader& document,
                                                   const std::shared_ptr<const mechanisms::Mechanism>& mechanism) {
  const auto factory = mechanism->capability<bodies::RigFactory>();
  if (!factory) document.fail("bodies", factory.reason());
  auto r = document.object("bodies");
  std::vector<std::string> fields = {"platform_joint"};
  for (auto& f : factory->part_fields()) fields.push_back(std::move(f));
  fields.insert(fields.end(), {"obstacles", "allowed_contacts"});
  r.declare_fields(fields);
  bodies::BodyModel model;
  if (r.has("platform_joint")) {
    auto p = r.object("platform_joint");
    p.declare_fields({"radius", "min_link_angle_deg"});
    Part part = leg_part("platform", PartKind::platform_joint, -1);
    part.radius = part_length(p, "radius", false);
    if (p.has("min_link_angle_deg")) {
      const double a = p.number("min_link_angle_deg");
      if (!(a >= 0.0 && a < 180.0)) p.fail("min_link_angle_deg", "must lie in [0, 180) degrees");
      model.min_link_angle = a * std::numbers::pi / 180.0;
    }
    p.finish();
    model.parts.push_back(part);
  }
  factory->read_parts(r, model);
  if (r.has("obstacles")) {
    const auto& v = r.raw("obstacles");
    if (!v.is_array()) r.fail("obstacles", "expected an array of {name, polygon}");
    auto items = r.objects("obstacles", v.size());
    for (auto& it : items) {
      it.declare_fields({"name", "polygon"});
      Part part;
      part.kind = PartKind::obstacle;
      part.name = it.string("name");
      if (part.name.empty()) it.fail("name", "must not be empty");
      if (model.find(part.name) >= 0) it.fail("name", "\"" + part.name + "\" is already the name of a part");
      part.polygon = read_polygon(it);
      it.finish();
      model.parts.push_back(part);
    }
  }
  if (r.has("allowed_contacts")) {
    const auto& v = r.raw("allowed_contacts");
    const std::string f = r.field("allowed_contacts");
    if (!v.is_array()) throw InputError(f + ": expected an array of [part, part] name pairs");
    for (std::size_t i = 0; i < v.size(); ++i) {
      const std::string where = item(f, i);
      const auto& e = v[i];
      if (!e.is_array() || e.size() != 2 || !e[0].is_string() || !e[1].is_string()) {
        throw InputError(where + ": expected [part, part] (two part names)");
      }
      const std::string a = e[0].get<std::string>(), b = e[1].get<std::string>();
      for (const auto& n : {a, b}) {
        if (model.find(n) < 0) throw InputError(where + ": no part named \"" + n + "\"");
      }
      if (a == b) throw InputError(where + ": a part cannot be paired with itself");
      model.allowed_contacts.emplace_back(a, b);
    }
  }
  r.finish();
  try {
    return factory->make(mechanism, std::move(model));
  } catch (const std::invalid_argument& e) {
    throw InputError(document.field("bodies") + ": " + e.what());
  }
}

}  // namespace pkmws::io::detail
