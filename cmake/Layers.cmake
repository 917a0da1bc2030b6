# trailray_layer(<target> <layer>): makes src/<layer>/ the headers of <target>, reachable as
# "<layer>/..." only through <target>'s own include directory, PUBLIC so that what links
# <target> sees them too and nothing else does.
#
# src/ itself is never an include directory (it would expose every layer to every target):
# each layer gets a folder in the build tree holding a single symbolic link, <layer> ->
# src/<layer>. A file in track/ that includes "render/..." then fails with "No such file",
# because trailray_track does not link trailray_render (tests/layering checks that it does).
function(trailray_layer target layer)
  set(root ${PROJECT_BINARY_DIR}/layer-include/${layer})
  file(MAKE_DIRECTORY ${root})
  if(NOT EXISTS ${root}/${layer})
    file(CREATE_LINK ${PROJECT_SOURCE_DIR}/src/${layer} ${root}/${layer} SYMBOLIC)
  endif()
  target_include_directories(${target} PUBLIC ${root})
endfunction()
