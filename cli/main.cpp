// hertzdash: command-line front end. Parses, validates, calls the library, prints.
// Exit codes: 0 success, 2 invalid input (the message names the parameter and
// its valid range), 1 any other failure. No output file is left half-written.
#include "cli/command.hpp"
#include "cli/help_formatter.hpp"
#include "cli/number_options.hpp"
#include "cli/option_suggestion.hpp"
#include "hertzdash/io/csv_table.hpp"
#include "hertzdash/io/provenance.hpp"
#include "hertzdash/model/invalid_parameter.hpp"

#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace {

// The subcommands' names, for the message when none or an unknown one is given.
std::string subcommand_names(const CLI::App& app) {
  std::string names;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    names += (names.empty() ? "" : ", ") + sub->get_name();
  return names;
}

// The first argument that is not an option: the subcommand asked for, or empty.
std::string first_word(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (argv[i][0] != '-') return argv[i];
  return {};
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"hertzdash: Hertz spring + nonlinear dashpot impact models (Hongo et al.)"};
  app.set_version_flag("--version", std::string("hertzdash ") + hertzdash::version() + " (git " +
                                         hertzdash::git_revision() + ")");
  app.require_subcommand(1);
  app.formatter(std::make_shared<hertzdash::cli::ShortHelpFormatter>());  // before the subcommands: they copy it
  std::vector<hertzdash::cli::Command> commands{
      hertzdash::cli::add_simulate_command(app),
      hertzdash::cli::add_models_command(app),
      hertzdash::cli::add_parameters_command(app),
      hertzdash::cli::add_restitution_command(app),
      hertzdash::cli::add_bounce_command(app),
  };
  for (const hertzdash::Rig& rig : hertzdash::rigs()) commands.push_back(hertzdash::cli::add_rig_command(app, rig));
  commands.push_back(hertzdash::cli::add_orbit_command(app));
  commands.push_back(hertzdash::cli::add_continue_command(app));
  commands.push_back(hertzdash::cli::add_lyapunov_command(app));
  commands.push_back(hertzdash::cli::add_basins_command(app));
  commands.push_back(hertzdash::cli::add_fit_command(app));
  commands.push_back(hertzdash::cli::add_export_command(app));
  commands.push_back(hertzdash::cli::add_conformance_command(app));
  commands.push_back(hertzdash::cli::add_sweep_command(app));

  try {
    app.parse(argc, argv);
    for (const auto& command : commands)
      if (command.subcommand->parsed()) return command.run();
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::RequiredError& e) {
    const std::vector<CLI::App*> parsed = app.get_subcommands();
    if (!parsed.empty() && !parsed.front()->get_subcommands([](const CLI::App*) { return true; }).empty()) {
      // A command of subcommands (`orbit RIG`) given none of them, or one it does not have.
      const CLI::App& command = *parsed.front();
      std::cerr << "hertzdash: `hertzdash " << command.get_name() << "` takes one of: " << subcommand_names(command)
                << " (hertzdash " << command.get_name() << " --help)\n";
    } else if (!parsed.empty()) {
      std::cerr << "hertzdash: " << e.what() << "\n";
    } else if (const std::string word = first_word(argc, argv); !word.empty()) {
      std::cerr << "hertzdash: unknown subcommand '" << word << "': the subcommands are " << subcommand_names(app)
                << " (hertzdash --help)\n";
    } else {
      std::cerr << "hertzdash: a subcommand is required: " << subcommand_names(app) << " (hertzdash --help)\n";
    }
    return 2;
  } catch (const CLI::ExtrasError& e) {  // an option the command does not have: name the nearest one
    const std::vector<CLI::App*> parsed = app.get_subcommands();
    const CLI::App& command = parsed.empty() ? app : *parsed.front();
    const std::string unknown = hertzdash::cli::unknown_options_message(command, argc, argv);
    std::cerr << "hertzdash: " << (unknown.empty() ? std::string(e.what()) : unknown) << " ("
              << (parsed.empty() ? std::string("hertzdash") : "hertzdash " + command.get_name()) << " --help)\n";
    return 2;
  } catch (const CLI::ParseError& e) {
    std::cerr << "hertzdash: " << e.what() << "\n";
    return 2;
  } catch (const hertzdash::InvalidParameter& e) {  // in the command line's spelling: --ball-E
    std::cerr << "hertzdash: " << hertzdash::cli::refusal_message(e) << "\n";
    return 2;
  } catch (const hertzdash::DataError& e) {
    std::cerr << "hertzdash: bad data file: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {  // a key named in the message, in the command line's spelling: --dt
    std::cerr << "hertzdash: error: " << hertzdash::spell_key_references(e.what(), hertzdash::KeySpelling::command_line)
              << "\n";
    return 1;
  }
  return 1;
}
