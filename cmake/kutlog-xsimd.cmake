# Finds xsimd 8.1. Debian 12's xsimd package lists `xtl` among the link libraries of its
# imported target without depending on it, and xtl is optional for xsimd: a consumer that
# links `xsimd` then fails with "cannot find -lxtl". Drop that entry when no xtl target exists.
# Used by kutlog's own build only: the installed package does not touch the xsimd target.
include(CMakeFindDependencyMacro)
find_dependency(xsimd 8.1)
if(TARGET xsimd AND NOT TARGET xtl)
  get_target_property(_kutlog_xsimd_links xsimd INTERFACE_LINK_LIBRARIES)
  if(_kutlog_xsimd_links)
    list(REMOVE_ITEM _kutlog_xsimd_links xtl)
    set_target_properties(xsimd PROPERTIES INTERFACE_LINK_LIBRARIES "${_kutlog_xsimd_links}")
  endif()
  unset(_kutlog_xsimd_links)
endif()
