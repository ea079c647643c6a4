# One static library per src/ folder, aliased froth::<name>. DEPS is the layering rule:
# a module may use only what it lists, and the linker enforces it.
function(froth_add_module name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS;PRIVATE_DEPS" ${ARGN})
  add_library(froth_${name} STATIC ${ARG_SOURCES})
  add_library(froth::${name} ALIAS froth_${name})
  target_include_directories(froth_${name} PUBLIC "${PROJECT_SOURCE_DIR}/src")
  target_link_libraries(froth_${name} PUBLIC ${ARG_DEPS} PRIVATE ${ARG_PRIVATE_DEPS})
  target_compile_options(froth_${name} PRIVATE -Wall -Wextra -Wshadow -Wpedantic
                         $<$<BOOL:${FROTH_WERROR}>:-Werror>)
endfunction()
