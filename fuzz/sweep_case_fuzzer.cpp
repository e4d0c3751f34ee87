// libFuzzer harness: the sweep case-file reader (simulation/sweep/sweep_case.hpp), from TOML text to
// the options of every run. Any input must parse or be refused with a DataError (not TOML) or
// an InvalidParameter (a key, type or value the format does not allow); a case that parsed must
// give the options of its first and last runs. No run is simulated.
#include "hertzdash/io/csv_table.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/sweep/sweep_case.hpp"

#include <cstddef>
#include <cstdint>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace hertzdash;
  try {
    const SweepCase c = parse_sweep_case(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.toml");
    if (c.size() == 0) return 0;
    (void)c.options(0);
    (void)c.options(c.size() - 1);
    (void)c.parameters(c.size() - 1);
  } catch (const DataError&) {
  } catch (const InvalidParameter&) {
  }
  return 0;
}
