// Export options and formats, atomic writes, the mechanism figure.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <unistd.h>

#include "pkmws/geometry/primitives.hpp"
#include "pkmws/io/export.hpp"
#include "pkmws/io/mechanism_file.hpp"
#include "support/export_cases.hpp"
#include "support/fixtures.hpp"

namespace {

namespace fs = std::filesystem;
using pkmws::geometry::Box;
using pkmws::geometry::Point;
using pkmws::geometry::Region;
namespace geo = pkmws::geometry;
namespace io = pkmws::io;
using pkmws::test::attribute;

using pkmws::test::count_of;
using pkmws::test::slurp;

TEST(ExportOptions, EffectiveToleranceAndMinArea) {
  const Region r = geo::rectangle(Box{{0.0, 0.0}, {3.0, 4.0}});
  EXPECT_DOUBLE_EQ(io::effective_tolerance(r, {}), 5e-6);  // 1e-6 of the diagonal 5
  EXPECT_DOUBLE_EQ(io::effective_min_area(r, {}), 12e-12);
  io::ExportOptions o;
  o.tolerance = 0.25;
  o.min_area = 1e-3;
  EXPECT_EQ(io::effective_tolerance(r, o), 0.25);
  EXPECT_EQ(io::effective_min_area(r, o), 1e-3);
}

TEST(ExportFormat, ParsesNamesAndRejectsOthers) {
  for (auto f : {io::ExportFormat::svg, io::ExportFormat::dxf, io::ExportFormat::wkt,
                 io::ExportFormat::geojson, io::ExportFormat::csv}) {
    EXPECT_EQ(io::parse_export_format(io::format_name(f)), f);
  }
  EXPECT_THROW(io::parse_export_format("pdf"), io::InputError);
}

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() /
                     ("pkmws_export_test_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

TEST(ExportWriteFile, OverwritesAtomicallyAndLeavesNoTemporary) {
  const fs::path d = fresh_dir("overwrite");
  const fs::path f = d / "out.svg";
  io::write_file_atomic(f, "first version, longer than the second\n");
  EXPECT_EQ(slurp(f), "first version, longer than the second\n");
  io::write_file_atomic(f, "second\n");
  EXPECT_EQ(slurp(f), "second\n");
  io::write_file_atomic(f, "");
  EXPECT_EQ(slurp(f), "");
  std::size_t entries = 0;
  for (const auto& e : fs::directory_iterator(d)) {
    ++entries;
    EXPECT_EQ(e.path().filename(), "out.svg");
  }
  EXPECT_EQ(entries, 1u);
  fs::remove_all(d);
}

TEST(ExportWriteFile, MissingDirectoryThrowsAndWritesNothing) {
  const fs::path d = fresh_dir("missing");
  const fs::path f = d / "no" / "such" / "dir" / "out.dxf";
  try {
    io::write_file_atomic(f, "content");
    ADD_FAILURE() << "no exception";
  } catch (const io::InputError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind(f.string() + ": cannot write: ", 0), 0u) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos);
  }
  EXPECT_FALSE(fs::exists(d / "no"));
  EXPECT_TRUE(fs::is_empty(d));
  // A directory in the way is refused too, and left as it was.
  fs::create_directory(d / "taken");
  EXPECT_THROW(io::write_file_atomic(d / "taken", "x"), io::InputError);
  EXPECT_TRUE(fs::is_directory(d / "taken"));
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(d)) ++entries;
  EXPECT_EQ(entries, 1u);
  fs::remove_all(d);
}

// -------------------------------------------------------------- figure

TEST(ExportFigure, MomaFigureIsWellFormed) {
  const fs::path file = fs::path(PKMWS_SOURCE_DIR) / "datasets" / "moma_m1_g0_l250.json";
  if (!fs::exists(file)) GTEST_SKIP() << file << " not there yet";
  const io::MechanismFile mech = io::load_mechanism(file);
  const Region region = mech.model->workspace();
  const auto comps = region.components();
  ASSERT_FALSE(comps.empty());
  const Point c = comps.front().centroid;
  io::FigureOptions opt;
  opt.title = mech.name;
  opt.caption = "exact workspace area = 36 202.18 mm² <M1 & l = 250>";
  const std::string svg = io::workspace_figure(mech, region, {c.x, c.y, 0.0}, opt);
  EXPECT_EQ(svg, io::workspace_figure(mech, region, {c.x, c.y, 0.0}, opt));  // deterministic
  EXPECT_EQ(count_of(svg, "<svg"), 1u);
  EXPECT_EQ(count_of(svg, "</svg>"), 1u);
  EXPECT_LT(svg.find("<svg"), svg.find("</svg>"));
  EXPECT_EQ(count_of(svg, "<g"), count_of(svg, "</g>"));
  EXPECT_NE(svg.find("exact workspace area = 36 202.18 mm² &lt;M1 &amp; l = 250&gt;"),
            std::string::npos);
  EXPECT_NE(svg.find(" A"), std::string::npos);
  // Every drawn element (lines, circles, rects, text anchors) lies on the canvas.
  double width = 0, height = 0;
  std::istringstream(attribute(svg, "svg", "width")) >> width;
  std::istringstream(attribute(svg, "svg", "height")) >> height;
  EXPECT_GE(width, 600);
  EXPECT_LE(width, 1000);
  EXPECT_GE(height, 500);
  EXPECT_LE(height, 900);
  std::size_t checked = 0;
  for (const std::string key : {" x1=\"", " x2=\"", " cx=\"", " x=\""}) {
    for (auto p = svg.find(key); p != std::string::npos; p = svg.find(key, p + 1)) {
      const double v = std::strtod(svg.c_str() + p + key.size(), nullptr);
      EXPECT_GE(v, 0.0);
      EXPECT_LE(v, width);
      ++checked;
    }
  }
  for (const std::string key : {" y1=\"", " y2=\"", " cy=\"", " y=\""}) {
    for (auto p = svg.find(key); p != std::string::npos; p = svg.find(key, p + 1)) {
      const double v = std::strtod(svg.c_str() + p + key.size(), nullptr);
      EXPECT_GE(v, 0.0);
      EXPECT_LE(v, height);
      ++checked;
    }
  }
  EXPECT_GT(checked, 20u);
  // The plot's mapping (data-transform="X0 Y0 S": px = X0 + S x, py = Y0 - S y)
  // puts the region's bounding box inside the canvas.
  const auto t = svg.find("data-transform=\"");
  ASSERT_NE(t, std::string::npos);
  double tx = 0, ty = 0, sx = 0;
  ASSERT_EQ(std::sscanf(svg.c_str() + t, "data-transform=\"%lf %lf %lf", &tx, &ty, &sx), 3);
  const double sy = -sx;
  EXPECT_GT(sx, 0.0);
  const Box b = region.bbox();
  for (const Point p : {b.min, b.max}) {
    EXPECT_GT(tx + sx * p.x, 0.0);
    EXPECT_LT(tx + sx * p.x, width);
    EXPECT_GT(ty + sy * p.y, 0.0);
    EXPECT_LT(ty + sy * p.y, height);
  }
}

}  // namespace
