# Sanitizers are applied to every target of the project (library, tests, CLI) so that the
# instrumented runtime is linked consistently. -O1 -g1 whatever the build type: line tables for
# the reports' stacks without the full debug information, which doubled the build's time.
function(coatfft_target_sanitizers target)
  if(COATFFT_SANITIZE)
    target_compile_options(${target} PRIVATE -fsanitize=address,undefined -fno-omit-frame-pointer
                                             -fno-sanitize-recover=undefined -O1 -g1)
    target_link_options(${target} PUBLIC -fsanitize=address,undefined)
  endif()
endfunction()
