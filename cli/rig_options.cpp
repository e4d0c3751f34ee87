// The options of a run of a rig (cli/rig_options.hpp).
#include "cli/rig_options.hpp"

#include "cli/number_options.hpp"
#include "cli/setup_options.hpp"
#include "hertzdash/simulation/rigs/rig_orbit.hpp"
#include "hertzdash/simulation/run/integrator_table.hpp"

#include <algorithm>

namespace hertzdash::cli {

void add_rig_options(CLI::App& sub, const Rig& rig, RunOptions& run, RigInputs& inputs, bool instantaneous) {
  add_run_options(sub, run);
  for (const RigOptionNote& n : rig.run_option_notes) sub.get_option("--" + std::string(n.key))->description(std::string(n.help));
  // The help lists what a run of the rig reads (issue 46): the options it never reads stay
  // options, refused with their reason when given, but out of the help: those the rig declares
  // unread, those of a trace, of the bounce sequence's flights, of the elastic rod and the tension
  // clamp (a rig's soft contacts are the rigid rod's, in regularising variables), and those no
  // integrator in regularising variables reads.
  for (const RunOption& option : run_options()) {
    const OptionReaders& r = option.readers;
    bool regularized_reads = !r.integrators;
    for (const IntegratorTraits& t : all_integrator_traits)
      regularized_reads = regularized_reads || (t.variables == Variables::regularized && r.integrators(t));
    const bool unread = std::ranges::find(rig.run_options_not_read, option.name) != rig.run_options_not_read.end() ||
                        (instantaneous && std::ranges::find(rig.instantaneous_reads, option.name) == rig.instantaneous_reads.end());
    if (unread || r.trace_only || r.flights_only || r.elastic_rod || option.name == "rod-model" ||
        (rig.regularized_contacts && (option.name == "no-tension" || !regularized_reads)))
      sub.get_option("--" + option.name)->group("");
  }
  const std::string group = "The " + std::string(rig.name) + " rig";
  for (const ParameterDecl& d : rig.inputs) {
    const std::string flag = "--" + std::string(d.key), key(d.key), help = help_text(d, KeySpelling::command_line);
    RigInputs* in = &inputs;
    CLI::Option* o =
        d.type == ParameterType::text
            ? sub.add_option_function<std::string>(flag, [in, key](const std::string& v) { in->texts[key] = v; }, help)
            : add_number_option(sub, flag, [in, key](double v) { in->numbers[key] = v; }, help);
    if (d.type == ParameterType::number && d.range.kind == NumberRange::Kind::integer) o->type_name("INT");
    o->group(group);
  }
  if (instantaneous) {
    inputs.texts[std::string(orbit_impact_model_note.key)] = std::string(orbit_impact_model);
    sub.get_option("--" + std::string(orbit_impact_model_note.key))->description(std::string(orbit_impact_model_note.help));
  }
}

}  // namespace hertzdash::cli
