# The sanitizer build: with -DSTEREOSHIFT_SANITIZE=ON (and CMAKE_CXX_COMPILER=clang++-14) every
# stereoshift target is built under AddressSanitizer + UndefinedBehaviorSanitizer, so the unit and lit
# tests run against an instrumented tool, and with libFuzzer's coverage instrumentation, so the fuzz
# targets of test/fuzz/ see which of our branches an input reached. The packaged libraries (glslang,
# SPIRV-Tools, SPIRV-Cross) stay uninstrumented: ASan still sees every allocation they make through
# the intercepted malloc/free, only their branches do not guide the fuzzer.
option(STEREOSHIFT_SANITIZE "Build with ASan + UBSan (clang) and the libFuzzer targets of test/fuzz" OFF)

if(STEREOSHIFT_SANITIZE)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "STEREOSHIFT_SANITIZE=ON needs clang, which ships libFuzzer: "
                        "-DCMAKE_CXX_COMPILER=clang++-14 (Debian: clang-14, libclang-rt-14-dev)")
  endif()
  # Undefined behaviour aborts like a memory error does: a test or a fuzz run must fail on it, not
  # print a line and carry on. Frame pointers keep the reports' stacks whole.
  set(STEREOSHIFT_SANITIZER_FLAGS -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_compile_options(${STEREOSHIFT_SANITIZER_FLAGS} -fsanitize=fuzzer-no-link)
  add_link_options(${STEREOSHIFT_SANITIZER_FLAGS})
endif()

# The packaged glslang is built without RTTI, and UBSan's vptr check needs the typeinfo of each
# polymorphic class it checks: the sources that use glslang's classes (TShader, TProgram, the
# intermediate tree) go without that one check; every other check stays on for them.
function(stereoshift_without_vptr_check directory)
  if(STEREOSHIFT_SANITIZE)
    set_source_files_properties(${ARGN} DIRECTORY ${directory} PROPERTIES COMPILE_OPTIONS -fno-sanitize=vptr)
  endif()
endfunction()
