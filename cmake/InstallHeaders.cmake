# Run by `cmake --install` (cmake/Install.cmake): copies GLOBE_PUBLIC_HEADERS (absolute paths under
# GLOBE_SOURCE_DIR) to PREFIX/GLOBE_INCLUDE_DIR/globe/<path>, each project include given the globe/
# prefix, so the installed tree has the one root a consumer includes <globe/...> from.
set(globe_include_root "$ENV{DESTDIR}${CMAKE_INSTALL_PREFIX}/${GLOBE_INCLUDE_DIR}/globe")
foreach(header IN LISTS GLOBE_PUBLIC_HEADERS)
  file(RELATIVE_PATH relative "${GLOBE_SOURCE_DIR}" "${header}")
  file(READ "${header}" text)
  string(REGEX REPLACE "#include \"(planet|engine|shaders)/" "#include \"globe/\\1/" text "${text}")
  file(WRITE "${globe_include_root}/${relative}" "${text}")
  list(APPEND CMAKE_INSTALL_MANIFEST_FILES "${globe_include_root}/${relative}")
endforeach()
list(LENGTH GLOBE_PUBLIC_HEADERS count)
message(STATUS "Installing: ${count} public headers under ${globe_include_root}")
