// moma files (SPEC §3.1): two legs {reference, guide_angle_deg, stroke,
// rod_length, branch}.
#include <numbers>

#include "io/loaders.hpp"
#include "pkmws/mechanisms/moma.hpp"

namespace pkmws::io::detail {

MechanismPtr load_moma(JsonReader& document) {
  std::array<mechanisms::MomaLeg, 2> legs;
  auto readers = document.objects("legs", 2);
  for (std::size_t i = 0; i < 2; ++i) {
    JsonReader& r = readers[i];
    mechanisms::MomaLeg& leg = legs[i];
    leg.reference = r.point("reference");
    leg.guide_angle = r.number("guide_angle_deg") * std::numbers::pi / 180.0;
    const auto stroke = r.interval("stroke");
    leg.stroke_min = stroke[0];
    leg.stroke_max = stroke[1];
    leg.rod_length = r.positive("rod_length");
    leg.branch = r.sign("branch");
    r.finish();
  }
  return std::make_shared<mechanisms::Moma>(legs);
}

}  // namespace pkmws::io::detail
