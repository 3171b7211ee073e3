# coatfft_add_program(name source...): a tool of the project (benchmark, validation table) linked
# against the library, with the project's warnings and sanitizers, and told where the sources are
# and which flags it was built with (benchmarks print them in their `# key = value` headers).
function(coatfft_add_program name)
  add_executable(${name} ${ARGN})
  target_link_libraries(${name} PRIVATE coatfft_internal)
  coatfft_target_warnings(${name})
  coatfft_target_sanitizers(${name})
  string(TOUPPER "${CMAKE_BUILD_TYPE}" build_type)
  target_compile_definitions(${name} PRIVATE COATFFT_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    COATFFT_BENCH_FLAGS="${CMAKE_BUILD_TYPE}: ${CMAKE_CXX_FLAGS} ${CMAKE_CXX_FLAGS_${build_type}}")
endfunction()
