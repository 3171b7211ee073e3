# Sanitizers are applied to every target of the project (library, tests, CLI) so that the
# instrumented runtime is linked consistently.
function(coatfft_target_sanitizers target)
  if(COATFFT_SANITIZE)
    target_compile_options(${target} PRIVATE -fsanitize=address,undefined -fno-omit-frame-pointer
                                             -fno-sanitize-recover=undefined)
    target_link_options(${target} PUBLIC -fsanitize=address,undefined)
  endif()
endfunction()
