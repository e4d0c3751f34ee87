# Instrumented builds (docs/reliability.md). Each goes into a build folder of its own.
#   -DHERTZDASH_SANITIZE=ON  `make sanitize`: AddressSanitizer + UndefinedBehaviorSanitizer, every
#                            report fatal; the whole ctest suite runs instrumented.
#   -DHERTZDASH_FUZZ=ON      `make fuzz` (clang only): the libraries instrumented for libFuzzer
#                            (plus ASan and UBSan) and the harnesses of fuzz/.
option(HERTZDASH_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer (make sanitize)" OFF)
option(HERTZDASH_FUZZ "Build the libFuzzer harnesses of fuzz/ (clang; make fuzz)" OFF)

# UBSan's null and alignment checks are left out: together they nearly double the compile time of the
# template-heavy units (a law's runs, generated/laws/hunt_crossley.cpp at -O1: 59 s with them, 34 s
# without, 18 s uninstrumented; either alone saves little), the larger part of CI's time. A null
# dereference still stops the run (ASan's SEGV report); x86 loads do not fault on misalignment.
set(HERTZDASH_SANITIZER_FLAGS -fsanitize=address,undefined -fno-sanitize=null,alignment -fno-sanitize-recover=all
    -fno-omit-frame-pointer)
if(HERTZDASH_SANITIZE)
  add_compile_options(${HERTZDASH_SANITIZER_FLAGS})
  add_link_options(${HERTZDASH_SANITIZER_FLAGS})
  # GCC 12 under ASan at -O1 warns of std::function members of std::regex's automaton as maybe
  # uninitialized (libstdc++ headers; not so without sanitizers): a known false positive.
  add_compile_options(-Wno-maybe-uninitialized)
  # python3 is not instrumented: to load the instrumented module, the ASan runtime must be
  # preloaded into it, and libstdc++ with it (else ASan's __cxa_throw interceptor finds no
  # libstdc++ at start-up and the first C++ exception kills the interpreter without a word).
  # Used by tests/CMakeLists.txt for the python and install tests.
  execute_process(COMMAND ${CMAKE_CXX_COMPILER} -print-file-name=libasan.so
    OUTPUT_VARIABLE asan_runtime OUTPUT_STRIP_TRAILING_WHITESPACE)
  execute_process(COMMAND ${CMAKE_CXX_COMPILER} -print-file-name=libstdc++.so
    OUTPUT_VARIABLE cxx_runtime OUTPUT_STRIP_TRAILING_WHITESPACE)
  set(HERTZDASH_SANITIZER_PRELOAD "${asan_runtime}:${cxx_runtime}")
endif()
if(HERTZDASH_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "HERTZDASH_FUZZ needs clang (libFuzzer): -DCMAKE_CXX_COMPILER=clang++")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
endif()

# Under HERTZDASH_FUZZ, a library that the harnesses link but never execute (the case-file reader
# needs the rig table, whose run functions need every law's runs) is compiled plain and
# unoptimised: the fuzzers read files, and the laws' units under -O3 with ASan would take most of
# `make fuzz`'s time.
function(hertzdash_not_fuzzed target)
  if(HERTZDASH_FUZZ)
    target_compile_options(${target} PRIVATE -O0 -fno-sanitize=all)
  endif()
endfunction()
