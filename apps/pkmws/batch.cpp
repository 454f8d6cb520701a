// pkmws batch FILES... --out DIR: the main job of `make demo`. For every
// mechanism file: what `pkmws area` reports, the figure `pkmws export -f svg`
// draws, and one row of a summary table (DIR/summary.md, DIR/summary.json);
// files without a planar workspace (a lone Pi-joint) are listed with the
// reason. The rows, figures and summaries are the library's (pkmws/report/batch.hpp).
#include <filesystem>
#include <iostream>

#include "cli.hpp"
#include "pkmws/io/export.hpp"
#include "pkmws/report/batch.hpp"

namespace pkmws::cli {

void add_batch(CLI::App& app, std::vector<Command>& commands) {
  auto* sub = app.add_subcommand("batch", "Areas and figures of many mechanism files, with a summary table");
  struct Args {
    std::vector<std::string> files;
    std::string out;
    bool json = false;
  };
  auto a = std::make_shared<Args>();
  sub->add_option("FILES", a->files, "Mechanism files (JSON)")->required();
  sub->add_option("--out,-o", a->out, "Output directory (created if missing)")->required();
  sub->add_flag("--json", a->json, "Print one JSON object: the summary rows (docs/schema/batch.output.schema.json)");
  commands.push_back({sub, [a] {
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::create_directories(a->out, ec);
    if (ec) throw io::InputError(a->out + ": cannot create directory: " + ec.message());
    // Load everything first: one bad file stops the run before anything is written.
    std::vector<io::MechanismFile> mechs;
    for (const auto& f : a->files) mechs.push_back(io::load_mechanism(f));
    report::BatchReport batch;
    batch.output_dir = a->out;
    for (const auto& mech : mechs) {
      report::BatchRow row = report::batch_row(mech);
      for (const auto& f : row.files) io::write_file_atomic(fs::path(a->out) / f.name, f.content);
      row.files.clear();
      if (!a->json) std::cout << report::to_text(row) << std::flush;
      batch.rows.push_back(std::move(row));
    }
    io::write_file_atomic(fs::path(a->out) / "summary.md", report::summary_markdown(batch));
    io::write_file_atomic(fs::path(a->out) / "summary.json", report::summary_json(batch));
    std::cout << (a->json ? report::to_json_text(batch) + "\n" : report::to_text(batch));
    return 0;
  }});
}

}  // namespace pkmws::cli
