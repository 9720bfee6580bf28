# regio_add_library(NAME FOLDER): the static library built from every .cpp
# below FOLDER (a top-level folder: model, solver, output, editor).
#
# Library seams are enforced by the include path. Sources include each other
# as "FOLDER/…" (#include "model/scene.h"), so the project root would do as
# include directory, but it would let every library see every other one.
# Instead each library gets a directory of its own in the build tree that
# holds nothing but a link named FOLDER to its sources, and exposes only that
# directory. A library sees its own headers and those of the libraries it
# links, never the others: a model file that includes "solver/…" or
# "editor/…" does not compile.
function(regio_add_library name folder)
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/${folder}/*.cpp)
  add_library(${name} STATIC ${sources})
  regio_expose_folder(${name} ${folder})
  target_link_libraries(${name} PRIVATE regio_warnings)
endfunction()

# regio_expose_folder(TARGET FOLDER): TARGET and whatever links it include
# FOLDER's headers as "FOLDER/…" through the build tree's link (see above).
function(regio_expose_folder target folder)
  set(dir ${PROJECT_BINARY_DIR}/include/${folder})
  file(MAKE_DIRECTORY ${dir})
  if(NOT EXISTS ${dir}/${folder})
    file(CREATE_LINK ${PROJECT_SOURCE_DIR}/${folder} ${dir}/${folder} SYMBOLIC)
  endif()
  target_include_directories(${target} PUBLIC ${dir})
endfunction()
