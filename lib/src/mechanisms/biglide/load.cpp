// biglide files (docs/format.md): half_width B, rods [l1, l2], stroke
// [[min, max], [min, max]], optional tool {l3, l4} for the real scheme
// ([Strutynskyi] fig. 4).
#include <cmath>
#include <stdexcept>

#include "io/registry.hpp"
#include "mechanisms/biglide/biglide.hpp"

namespace pkmws::io::detail {

MechanismPtr load_biglide(JsonReader& document) {
  mechanisms::BiglideParams p;
  p.meters_per_unit = document.string("units") == "m" ? 1.0 : 1e-3;
  p.half_width = document.positive("half_width");
  const auto rods = document.numbers("rods", 2);
  for (std::size_t i = 0; i < 2; ++i) {
    if (!(rods[i] > 0.0)) {
      throw InputError(item(document.field("rods"), i) + ": must be positive");
    }
    p.rods[i] = rods[i];
  }
  const auto& stroke = document.raw("stroke");
  const std::string f = document.field("stroke");
  if (!stroke.is_array() || stroke.size() != 2) throw InputError(f + ": expected [[min, max], [min, max]], one per slider");
  for (std::size_t i = 0; i < 2; ++i) {
    const std::string where = item(f, i);
    const auto& s = stroke[i];
    if (!s.is_array() || s.size() != 2 || !s[0].is_number() || !s[1].is_number()) {
      throw InputError(where + ": expected [min, max]");
    }
    const double lo = s[0].get<double>(), hi = s[1].get<double>();
    if (!std::isfinite(lo) || !std::isfinite(hi) || !(lo < hi)) throw InputError(where + ": expected [min, max] with min < max");
    p.strokes[i] = {lo, hi};
  }
  if (document.has("tool")) {
    auto t = document.object("tool");
    t.declare_fields({"l3", "l4"});
    mechanisms::BiglideTool tool;
    tool.l3 = t.positive("l3");
    tool.l4 = t.non_negative("l4");
    t.finish();
    const double l1 = p.rods[0];
    if (tool.l4 > l1 + tool.l3 || tool.l4 < std::abs(l1 - tool.l3)) {
      t.fail("l4", "the triangle S1 J T needs |l1 - l3| <= l4 <= l1 + l3 (l1 = rods[0])");
    }
    p.tool = tool;
  }
  try {
    return std::make_shared<mechanisms::Biglide>(p);
  } catch (const std::invalid_argument& e) {
    throw InputError(e.what());
  }
}

// The module's file keywords with their loaders and top-level fields (docs/format.md).
std::vector<Kind> biglide_kinds() {
  return {{"biglide", load_biglide, {"half_width", "rods", "stroke", "tool"}}};
}

}  // namespace pkmws::io::detail
