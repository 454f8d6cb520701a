// pkmws: exact workspaces of planar parallel mechanisms (docs/format.md (command line)).
#include <cstdio>
#include <exception>
#include <iostream>

#include "cli.hpp"

int main(int argc, char** argv) {
  CLI::App app{"pkmws: exact workspaces of planar parallel mechanisms", "pkmws"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "pkmws 0.1.0");
  std::vector<pkmws::cli::Command> commands;
  pkmws::cli::add_area(app, commands);
  pkmws::cli::add_export(app, commands);
  pkmws::cli::add_kinematics(app, commands);
  pkmws::cli::add_info(app, commands);
  pkmws::cli::add_batch(app, commands);
  pkmws::cli::add_plot(app, commands);
  pkmws::cli::add_grid(app, commands);
  pkmws::cli::add_compare(app, commands);
  pkmws::cli::add_levels(app, commands);
  pkmws::cli::add_explain(app, commands);
  pkmws::cli::add_sweep(app, commands);
  pkmws::cli::add_atlas(app, commands);
  pkmws::cli::add_diff(app, commands);
  pkmws::cli::add_chart(app, commands);
  pkmws::cli::add_optimize(app, commands);
  pkmws::cli::add_feasible(app, commands);
  pkmws::cli::strict_numeric_options(app);
  if (argc > 1 && argv[1][0] != '-') {
    bool known = false;
    std::string names;
    for (const auto* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
      known = known || sub->get_name() == argv[1];
      names += (names.empty() ? "" : ", ") + sub->get_name();
    }
    if (!known) {
      std::cerr << "pkmws: error: unknown command \"" << argv[1] << "\" (expected one of: " << names << ")\n";
      return 2;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // Name the command and what it expects (its positional values), e.g.
    // "area: The following argument was not expected: 5 (expected: pkmws area FILE [options])".
    for (const auto* sub : app.get_subcommands([](const CLI::App*) { return true; })) {
      if (!sub->parsed()) continue;
      std::string usage;
      for (const auto* o : sub->get_options([](const CLI::Option* o) { return o->get_positional(); })) {
        const std::string name = o->get_name(true, false);
        usage += " " + (o->get_required() ? name : "[" + name + "]");
      }
      std::cerr << "pkmws: error: " << sub->get_name() << ": " << e.what() << " (expected: pkmws " << sub->get_name()
                << usage << " [options]; see pkmws " << sub->get_name() << " --help)\n";
      return 2;
    }
    std::cerr << "pkmws: error: " << e.what() << " (see pkmws --help)\n";
    return 2;
  }
  try {
    for (const auto& c : commands) {
      if (c.app->parsed()) return c.run();
    }
  } catch (const std::exception& e) {
    // Bad input of any kind: one line, exit status 2, nothing half-written.
    std::string message = e.what();
    for (char& ch : message) {
      if (ch == '\n') ch = ' ';
    }
    std::cout.flush();
    std::cerr << "pkmws: error: " << message << "\n";
    return 2;
  }
  return 2;
}
