# Every dependency comes from Debian 12 packages; nothing is downloaded at configure time.
# See ../shared/docs/dependencies.md for what each package ships.

find_package(Eigen3 3.4 REQUIRED NO_MODULE)                      # Eigen3::Eigen
find_package(PNG REQUIRED)                                        # PNG::PNG (snapshots)

# SuiteSparse 5.12 (Debian 12) ships no CMake config; SuiteSparse >= 7 does.
find_package(CHOLMOD CONFIG QUIET)
find_package(UMFPACK CONFIG QUIET)
if(NOT TARGET SuiteSparse::CHOLMOD)
  find_path(SUITESPARSE_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse REQUIRED)
  foreach(_l cholmod umfpack amd camd colamd ccolamd suitesparseconfig)
    string(TOUPPER ${_l} _L)
    find_library(SS_${_L}_LIB NAMES ${_l} REQUIRED)
  endforeach()
  add_library(SuiteSparse::CHOLMOD INTERFACE IMPORTED)
  target_include_directories(SuiteSparse::CHOLMOD INTERFACE ${SUITESPARSE_INCLUDE_DIR})
  target_link_libraries(SuiteSparse::CHOLMOD INTERFACE ${SS_CHOLMOD_LIB} ${SS_AMD_LIB}
    ${SS_CAMD_LIB} ${SS_COLAMD_LIB} ${SS_CCOLAMD_LIB} ${SS_SUITESPARSECONFIG_LIB})
  add_library(SuiteSparse::UMFPACK INTERFACE IMPORTED)
  target_include_directories(SuiteSparse::UMFPACK INTERFACE ${SUITESPARSE_INCLUDE_DIR})
  target_link_libraries(SuiteSparse::UMFPACK INTERFACE ${SS_UMFPACK_LIB} SuiteSparse::CHOLMOD)
endif()

# Lua 5.4 built as C++ (lua5.4-c++): lua_error throws, so C++ destructors run on Lua errors.
find_path(LUA_INCLUDE_DIR lua.hpp PATH_SUFFIXES lua5.4 REQUIRED NO_DEFAULT_PATH
  PATHS /usr/include /usr/local/include)
find_library(LUA_CXX_LIBRARY NAMES lua5.4-c++ REQUIRED)
add_library(Lua::Lua INTERFACE IMPORTED)
target_include_directories(Lua::Lua INTERFACE ${LUA_INCLUDE_DIR})
target_link_libraries(Lua::Lua INTERFACE ${LUA_CXX_LIBRARY} m)

find_path(READLINE_INCLUDE_DIR readline/readline.h REQUIRED)
find_library(READLINE_LIB readline REQUIRED)
add_library(Readline::Readline INTERFACE IMPORTED)
target_include_directories(Readline::Readline INTERFACE ${READLINE_INCLUDE_DIR})
target_link_libraries(Readline::Readline INTERFACE ${READLINE_LIB})

if(FROTH_WITH_GMSH)
  find_path(GMSH_INCLUDE_DIR gmsh.h REQUIRED)
  find_library(GMSH_LIB NAMES gmsh REQUIRED)
  add_library(Gmsh::Gmsh INTERFACE IMPORTED)
  target_include_directories(Gmsh::Gmsh INTERFACE ${GMSH_INCLUDE_DIR})
  target_link_libraries(Gmsh::Gmsh INTERFACE ${GMSH_LIB})
endif()

# CGAL is header-only; found and wired here, linked only into the checks TUs of later issues.
if(FROTH_WITH_CGAL)
  set(CGAL_DO_NOT_WARN_ABOUT_CMAKE_BUILD_TYPE TRUE)
  find_package(CGAL 5.5 QUIET)
  if(CGAL_FOUND)
    message(STATUS "froth: CGAL ${CGAL_VERSION} found")
  else()
    message(STATUS "froth: CGAL not found; geometry checks that need it stay off")
  endif()
endif()
