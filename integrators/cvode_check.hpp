#pragma once
// Every SUNDIALS return code checked: failures name the call and CVODE's flag. For the .cpp
// files that call CVODE(S) directly (integrators/cvode_integrator.cpp,
// validation/common/contact_sensitivity.cpp, bench/cvode_fresh_peer.cpp); it includes SUNDIALS'
// header, so no public header includes it.
#include <cvodes/cvodes.h>

#include <cstdlib>
#include <stdexcept>
#include <string>

namespace hertzdash {

/// Throws std::runtime_error "<library>: <call> failed with <flag name>" for a negative flag.
inline void check_cvode_flag(int flag, const char* call, const char* library = "CVODE") {
  if (flag < 0) {
    char* name = CVodeGetReturnFlagName(flag);  // malloc'ed by SUNDIALS: ours to free
    const std::string text = std::string(library) + ": " + call + " failed with " + (name ? name : "?");
    std::free(name);
    throw std::runtime_error(text);
  }
}

/// p, or throws std::runtime_error "<library>: <call> returned NULL".
template <class T> T* check_cvode_ptr(T* p, const char* call, const char* library = "CVODE") {
  if (p == nullptr) throw std::runtime_error(std::string(library) + ": " + call + " returned NULL");
  return p;
}

}  // namespace hertzdash
