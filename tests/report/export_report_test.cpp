// The export report (pkmws/report/export.hpp): the GeoJSON of the toy annulus
// encloses 40π (shoelace over its rings), the figure states the area, the
// JSON line about the file, and the refusals naming the option.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <nlohmann/json.hpp>

#include "pkmws/core/error.hpp"
#include "pkmws/report/export.hpp"
#include "support/fixtures.hpp"
#include "support/report_fixtures.hpp"

namespace pkmws {
namespace {

constexpr double kAnnulus = 40 * std::numbers::pi;

double ring_area(const nlohmann::json& ring) {
  double twice = 0.0;
  for (std::size_t k = 0; k + 1 < ring.size(); ++k) {
    twice += ring[k][0].get<double>() * ring[k + 1][1].get<double>() - ring[k + 1][0].get<double>() * ring[k][1].get<double>();
  }
  return 0.5 * twice;
}

TEST(ReportExport, GeojsonOfTheAnnulusEnclosesItsArea) {
  report::ExportOptions o;
  o.format = io::ExportFormat::geojson;
  o.output = "ring.geojson";
  const report::ExportReport r = report::export_file(test::toy_annulus_file(), o);
  EXPECT_FALSE(r.stopped);
  EXPECT_EQ(r.content, "boundary");
  EXPECT_EQ(r.bound, "");  // exact
  const auto g = test::parsed(r.text);
  // One polygon with a hole; polylines within the default deviation of the arcs.
  const auto& geometry = g["features"][0]["geometry"];
  ASSERT_EQ(geometry["type"], "MultiPolygon");
  ASSERT_EQ(geometry["coordinates"].size(), 1u);
  const auto& polygon = geometry["coordinates"][0];
  ASSERT_EQ(polygon.size(), 2u);
  const double area = std::abs(ring_area(polygon[0])) - std::abs(ring_area(polygon[1]));
  EXPECT_NEAR(area, kAnnulus, 1e-4 * kAnnulus);
  const auto j = test::parsed(report::to_json_text(r));
  EXPECT_EQ(j["format"], "geojson");
  EXPECT_EQ(j["output"], "ring.geojson");
  EXPECT_EQ(j["content"], "boundary");
  EXPECT_TRUE(j["bound"].is_null());
  EXPECT_EQ(j["bound_reason"], "the region is exact (or a figure), not one of two enclosures");
}

TEST(ReportExport, TheFigureStatesTheArea) {
  report::ExportOptions o;
  o.output = "fig.svg";
  const report::ExportReport r = report::export_file(test::toy_annulus_file(), o);
  EXPECT_EQ(r.content, "figure");
  EXPECT_NE(r.text.find("Exact workspace area = 125.6637061 mm²"), std::string::npos);
  o.bare = true;
  const report::ExportReport bare = report::export_file(test::toy_annulus_file(), o);
  EXPECT_EQ(bare.content, "boundary");
  EXPECT_EQ(bare.text.find("Exact workspace area"), std::string::npos);
}

TEST(ReportExport, RefusalsNameTheOption) {
  const io::MechanismFile f = test::toy_annulus_file();
  const auto message = [&](const report::ExportOptions& o) {
    try {
      report::export_file(f, o);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  report::ExportOptions o;
  o.criterion = "pressure_angle";
  EXPECT_EQ(message(o), "--criterion and --levels go together");
  o.levels = {10, 20};
  o.format = io::ExportFormat::dxf;
  EXPECT_EQ(message(o), "--criterion: the bands export as svg (figure) or csv (traced level curves)");
  o = {};
  o.format = io::ExportFormat::wkt;
  o.tolerance = -1.0;
  EXPECT_EQ(message(o), "--tolerance: must be a positive finite length");
  o.tolerance.reset();
  o.real = true;
  EXPECT_EQ(message(o), "toy_annulus.json: --real needs `bodies` in the file (docs/format.md (bodies))");
}

}  // namespace
}  // namespace pkmws
