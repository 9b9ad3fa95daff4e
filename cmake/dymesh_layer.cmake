# A layer of the house: the static library dymesh_<name> (alias and export name dymesh::<name>) of
# the calling folder's sources, its include/ folder public; the layer adds its own links.
function(dymesh_layer name)
  add_library(dymesh_${name} ${ARGN})
  add_library(dymesh::${name} ALIAS dymesh_${name})
  set_target_properties(dymesh_${name} PROPERTIES EXPORT_NAME ${name} POSITION_INDEPENDENT_CODE ON)
  target_include_directories(dymesh_${name} PUBLIC $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
                                                   $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
endfunction()
