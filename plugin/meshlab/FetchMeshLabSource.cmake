# MeshLab's headers for plugins (src/common, vcglib) come only with Debian's
# source package. Fetch the version matching the installed meshlab into the
# build tree with a private apt state, leaving the machine's apt
# configuration alone.
#   out: MESHLAB_SOURCE_DIR (the unpacked package)
function(cm_fetch_meshlab_source dest)
  set(MESHLAB_SOURCE_DIR ${dest}/src PARENT_SCOPE)
  if(EXISTS ${dest}/src/src/common/interfaces.h)
    return()
  endif()
  foreach(tool apt-get dpkg-source dpkg-query)
    find_program(CM_${tool}_PROGRAM ${tool})
    if(NOT CM_${tool}_PROGRAM)
      message(FATAL_ERROR "CM_WITH_MESHLAB: ${tool} not found (install the Debian package dpkg-dev)")
    endif()
  endforeach()
  execute_process(COMMAND ${CM_dpkg-query_PROGRAM} -W -f=\${Version} meshlab
                  OUTPUT_VARIABLE version RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0 OR version STREQUAL "")
    message(FATAL_ERROR "CM_WITH_MESHLAB: MeshLab is not installed (install the Debian package meshlab)")
  endif()
  message(STATUS "Fetching the source package of meshlab ${version} into ${dest}")
  file(MAKE_DIRECTORY ${dest}/apt/lists/partial ${dest}/apt/cache/archives/partial)
  file(WRITE ${dest}/apt/sources.list
       "deb-src [signed-by=/usr/share/keyrings/debian-archive-keyring.gpg] http://deb.debian.org/debian bookworm main\n")
  set(apt_options
      -o Dir::Etc::SourceList=${dest}/apt/sources.list -o Dir::Etc::SourceParts=/dev/null
      -o Dir::State::Lists=${dest}/apt/lists -o Dir::Cache=${dest}/apt/cache)
  execute_process(COMMAND ${CM_apt-get_PROGRAM} ${apt_options} -qq update RESULT_VARIABLE rc)
  if(rc EQUAL 0)
    execute_process(COMMAND ${CM_apt-get_PROGRAM} ${apt_options} -qq source --download-only meshlab=${version}
                    WORKING_DIRECTORY ${dest} RESULT_VARIABLE rc)
  endif()
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "CM_WITH_MESHLAB: apt-get source meshlab=${version} failed (network, or the version left the archive)")
  endif()
  file(GLOB dsc ${dest}/meshlab_*.dsc)
  # apt-get checked the files against the signed Sources index, so the
  # .dsc signature check (which needs the uploader keys) is skipped.
  execute_process(COMMAND ${CM_dpkg-source_PROGRAM} --no-check -x ${dsc} ${dest}/src
                  OUTPUT_QUIET RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0 OR NOT EXISTS ${dest}/src/src/common/interfaces.h)
    message(FATAL_ERROR "CM_WITH_MESHLAB: unpacking ${dsc} failed")
  endif()
endfunction()
