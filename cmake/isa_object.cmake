# wavetrace_isa_object(OUT_VAR NAME SOURCE FLAGS flags... [EXPORT patterns...] [LINK targets...])
#
# Compiles SOURCE with an instruction set's target FLAGS (e.g. -mavx512f ...) into one object
# file in which every defined symbol is local except those matching the EXPORT patterns
# (objcopy wildcards), and stores that object's path in OUT_VAR, to be listed as a source.
#
# Why: a TU compiled with -mavx512f emits its own copy of every inline function and template it
# uses, std:: and gtest's included (vector<string>::emplace_back, ...), encoded for AVX-512. The
# linker keeps one copy of each for the whole binary, and may keep that one: then code for any
# CPU calls AVX-512 instructions and dies with SIGILL on a CPU without them. Our own code is
# kept apart by the per-ISA namespaces (src/simd/isa.h), but std:: cannot be renamed. So the
# object is linked on its own first (ld -r, with --force-group-allocation resolving its COMDAT
# groups inside it) and its symbols made local (objcopy): its copies can only ever be called
# from inside it, and the rest of the binary keeps its own. tests/isa_isolation_test.sh checks
# the result in the binaries.
#
# LINK: targets whose usage requirements (include directories, definitions) the TU needs.
# GNU ld for the partial link (clang's CMAKE_LINKER may be lld, which lacks --force-group-allocation).
find_program(WAVETRACE_PARTIAL_LINKER NAMES ld.bfd ld REQUIRED)
function(wavetrace_isa_object out name source)
  cmake_parse_arguments(PARSE_ARGV 3 arg "" "" "FLAGS;EXPORT;LINK")
  add_library(${name}_compile OBJECT ${source})
  # -fno-gnu-unique: g++ gives an inline function's static variables STB_GNU_UNIQUE binding,
  # which objcopy cannot make local; as weak symbols they are localized like the rest.
  target_compile_options(${name}_compile PRIVATE ${arg_FLAGS} $<$<CXX_COMPILER_ID:GNU>:-fno-gnu-unique>)
  target_link_libraries(${name}_compile PRIVATE ${arg_LINK})
  if(arg_EXPORT)
    set(visibility --wildcard)
    foreach(pattern IN LISTS arg_EXPORT)
      list(APPEND visibility --keep-global-symbol=${pattern})
    endforeach()
  else()
    set(visibility --wildcard --localize-symbol=*)
  endif()
  set(isolated ${CMAKE_CURRENT_BINARY_DIR}/${name}.isolated.o)
  add_custom_command(
    OUTPUT ${isolated}
    COMMAND ${WAVETRACE_PARTIAL_LINKER} -r --force-group-allocation -o ${isolated}.partial $<TARGET_OBJECTS:${name}_compile>
    COMMAND ${CMAKE_OBJCOPY} ${visibility} ${isolated}.partial ${isolated}
    COMMAND ${CMAKE_COMMAND} -E rm -f ${isolated}.partial
    DEPENDS ${name}_compile $<TARGET_OBJECTS:${name}_compile>
    COMMENT "Isolating the ${name} object's symbols"
    VERBATIM COMMAND_EXPAND_LISTS)
  set_source_files_properties(${isolated} PROPERTIES EXTERNAL_OBJECT TRUE GENERATED TRUE)
  set(${out} ${isolated} PARENT_SCOPE)
endfunction()
