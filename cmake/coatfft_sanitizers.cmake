# Sanitizers are applied to every target of the project (library, tests, CLI) so that the
# instrumented runtime is linked consistently. -O1 -g1 whatever the build type: line tables for
# the reports' stacks without the full debug information, which doubled the build's time.
# coatfft_target_sanitizers(target THIN): code that spends its time in the library (a Catch2 test
# program, the command line's front end), compiled at -Og instead: under the sanitizers Catch2's
# assertion macros and CLI11's parsers take twice as long to compile at -O1 (40 s against 21 s for
# tests/test_contact.cpp; 63 s for cli/main.cpp), and the work they check or start runs in the
# library, which keeps -O1. The sanitizers instrument both levels alike.
function(coatfft_target_sanitizers target)
  if(COATFFT_SANITIZE)
    if("${ARGN}" STREQUAL "THIN")
      set(level -Og)
    else()
      set(level -O1)
    endif()
    target_compile_options(${target} PRIVATE -fsanitize=address,undefined -fno-omit-frame-pointer
                                             -fno-sanitize-recover=undefined ${level} -g1)
    target_link_options(${target} PUBLIC -fsanitize=address,undefined)
  endif()
endfunction()
