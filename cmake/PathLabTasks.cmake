# Every task file is compiled twice into OBJECT libraries with the same symbols:
#   pathlab_taskN_student    from tasks/NN-name/FILE.cpp   (the student's TODOs)
#   pathlab_taskN_reference  from solutions/NN-name/FILE.cpp
# An executable links one of the two per task. A task file uses the task
# APIs and the layers below them only (pathlab_tasks: framework/tasks, core,
# util); the render and debug layers (static libraries that call the task
# functions) resolve against whichever implementation the executable chose:
# OBJECT libraries always link, in any order.

#
# The task list is the folders tasks/NN-name/, numbered from 01: the suites,
# the validity matrix, the debuggers, the seed runs and the grader all derive
# from them (tools read them through tools/pathlab_tasks.py). Task NN's
# student file is tasks/NN-name/name.cpp, the name's dashes as underscores.
#   PATHLAB_TASK_NAMES   01-camera-rays;02-intersection;...
#   PATHLAB_TASK_DIRS    01-camera-rays/camera_rays.cpp;...
#   PATHLAB_TASK_COUNT   7
file(GLOB _pathlab_task_folders LIST_DIRECTORIES true RELATIVE ${CMAKE_SOURCE_DIR}/tasks
     CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/tasks/[0-9][0-9]-*)
list(SORT _pathlab_task_folders)
set(PATHLAB_TASK_NAMES "")
set(PATHLAB_TASK_DIRS "")
foreach(folder IN LISTS _pathlab_task_folders)
  if(IS_DIRECTORY ${CMAKE_SOURCE_DIR}/tasks/${folder})
    list(LENGTH PATHLAB_TASK_NAMES count)
    math(EXPR expected "${count} + 1")
    string(SUBSTRING ${folder} 0 2 number)
    if(NOT number EQUAL expected)
      message(FATAL_ERROR "tasks/${folder}: expected task ${expected} here (tasks/NN-name/ from 01, no gaps)")
    endif()
    string(REGEX REPLACE "^[0-9][0-9]-" "" stem ${folder})
    string(REPLACE "-" "_" stem ${stem})
    list(APPEND PATHLAB_TASK_NAMES ${folder})
    list(APPEND PATHLAB_TASK_DIRS ${folder}/${stem}.cpp)
  endif()
endforeach()
list(LENGTH PATHLAB_TASK_NAMES PATHLAB_TASK_COUNT)

# pathlab_task_identifier(folder out): the task's name in C++ identifiers,
# "01-camera-rays" -> CameraRays: its debugger.cpp defines add<it>Views and
# its lab_warps.cpp (where it has warps) add<it>Warps.
function(pathlab_task_identifier folder out)
  string(REGEX REPLACE "^[0-9][0-9]-" "" stem ${folder})
  string(REPLACE "-" ";" words ${stem})
  set(id "")
  foreach(word IN LISTS words)
    string(SUBSTRING ${word} 0 1 first)
    string(SUBSTRING ${word} 1 -1 rest)
    string(TOUPPER ${first} first)
    string(APPEND id ${first}${rest})
  endforeach()
  set(${out} ${id} PARENT_SCOPE)
endfunction()

# pathlab_task_names(n title label): what the programs call task n, from its
# folder: the handout's first line "# Task N — Title", and the label of
# tasks/NN-name/task.json (the GUI's name for its panel; tools/pathlab_tasks.py
# reads the same file and checks the rest of it). Both as C++ string contents.
function(pathlab_task_names n title_out label_out)
  math(EXPR i "${n} - 1")
  list(GET PATHLAB_TASK_NAMES ${i} folder)
  set(readme ${CMAKE_SOURCE_DIR}/tasks/${folder}/README.md)
  set(manifest ${CMAKE_SOURCE_DIR}/tasks/${folder}/task.json)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${readme} ${manifest})
  file(STRINGS ${readme} first LIMIT_COUNT 1 ENCODING UTF-8)
  if(NOT first MATCHES "^# Task ${n} — (.+)$")
    message(FATAL_ERROR "tasks/${folder}/README.md should start \"# Task ${n} — Title\", not \"${first}\"")
  endif()
  string(REPLACE "–" "-" title "${CMAKE_MATCH_1}")  # the GUI's font has no en dash
  if(NOT EXISTS ${manifest})
    message(FATAL_ERROR "tasks/${folder}/task.json is missing (every task folder has one: docs/architecture.md, \"The task list\")")
  endif()
  file(READ ${manifest} json)
  string(JSON label ERROR_VARIABLE error GET "${json}" label)
  if(error)
    message(FATAL_ERROR "tasks/${folder}/task.json: no \"label\" (${error})")
  endif()
  foreach(var title label)
    string(REPLACE "\\" "\\\\" ${var} "${${var}}")
    string(REPLACE "\"" "\\\"" ${var} "${${var}}")
  endforeach()
  set(${title_out} "${title}" PARENT_SCOPE)
  set(${label_out} "${label}" PARENT_SCOPE)
endfunction()

# The tasks the course hands out, PATHLAB_HANDED_OUT (numbers): a student
# release lists them in tasks/handed-out.txt (tools/make-student-release
# --tasks; comma-separated, '#' starts a comment); the course repository has
# no such file and hands out every task. A task not handed out links the
# reference (pathlab_task_variant) and has no suite.
set(PATHLAB_HANDED_OUT "")
if(EXISTS ${CMAKE_SOURCE_DIR}/tasks/handed-out.txt)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/tasks/handed-out.txt)
  file(STRINGS ${CMAKE_SOURCE_DIR}/tasks/handed-out.txt _pathlab_lines)
  foreach(line IN LISTS _pathlab_lines)
    string(REGEX REPLACE "#.*" "" line "${line}")
    string(REPLACE "," ";" numbers "${line}")
    foreach(number IN LISTS numbers)
      string(STRIP "${number}" number)
      if(number STREQUAL "")
        continue()
      endif()
      if(NOT number MATCHES "^[0-9]+$" OR number LESS 1 OR number GREATER PATHLAB_TASK_COUNT)
        message(FATAL_ERROR "tasks/handed-out.txt: '${number}' is not a task number (1 to ${PATHLAB_TASK_COUNT})")
      endif()
      math(EXPR number "${number}")  # "08" -> 8
      list(APPEND PATHLAB_HANDED_OUT ${number})
    endforeach()
  endforeach()
  if(NOT PATHLAB_HANDED_OUT)
    message(FATAL_ERROR "tasks/handed-out.txt lists no task")
  endif()
else()
  foreach(n RANGE 1 ${PATHLAB_TASK_COUNT})
    list(APPEND PATHLAB_HANDED_OUT ${n})
  endforeach()
endif()

# Where the student files come from: tasks/ by default; a TA grading a
# submission points PATHLAB_STUDENT_DIR at it (files either as the
# tasks/NN-name/ tree or flat by file name). A task file missing from the
# submission falls back to the untouched stub in tasks/.
set(PATHLAB_STUDENT_DIR ${CMAKE_SOURCE_DIR}/tasks CACHE PATH "Folder with the student's task files")

function(pathlab_add_tasks)
  set(n 0)
  foreach(rel IN LISTS PATHLAB_TASK_DIRS)
    math(EXPR n "${n} + 1")
    get_filename_component(file ${rel} NAME)
    foreach(variant student reference)
      if(variant STREQUAL student)
        if(EXISTS ${PATHLAB_STUDENT_DIR}/${rel})
          set(src ${PATHLAB_STUDENT_DIR}/${rel})
        elseif(EXISTS ${PATHLAB_STUDENT_DIR}/${file})
          set(src ${PATHLAB_STUDENT_DIR}/${file})
        else()
          set(src ${CMAKE_SOURCE_DIR}/tasks/${rel})
        endif()
      else()
        set(src ${CMAKE_SOURCE_DIR}/solutions/${rel})
      endif()
      if(EXISTS ${src})
        add_library(pathlab_task${n}_${variant} OBJECT ${src})
        target_link_libraries(pathlab_task${n}_${variant} PUBLIC pathlab_tasks)
      endif()
    endforeach()
  endforeach()
  if(EXISTS ${CMAKE_SOURCE_DIR}/solutions)
    pathlab_add_reference_objects_target()
    set(status "source: solutions/")
  else()
    pathlab_import_reference_objects(status)
  endif()
  foreach(n RANGE 1 ${PATHLAB_TASK_COUNT})
    if(NOT n IN_LIST PATHLAB_HANDED_OUT AND NOT TARGET pathlab_task${n}_reference)
      message(STATUS "PathLab: task ${n} is not handed out in this course, and there is no compiled reference "
                     "for it here: its stub stands in (scenes that need task ${n} render wrongly)")
    endif()
  endforeach()
  # Read by tools/check: where this build's reference comes from.
  set(PATHLAB_REFERENCE_STATUS "${status}" CACHE INTERNAL "Where the reference tasks come from")
  file(WRITE ${CMAKE_BINARY_DIR}/pathlab-reference.txt "${status}\n")
endfunction()

# ---- The reference as compiled objects ---------------------------------
# The student release has no solutions/, but may carry the reference
# compiled, one folder per platform: reference-objects/PLATFORM/task-N.o
# and manifest.json (tools/make-student-release copies what the target
# pathlab-reference-objects makes). Where one matches the compiler and the
# framework headers, the judges and every candidate link the same
# reference as the grader, so tools/check predicts the grade; elsewhere
# the reference falls back to the student's own files (and says so).

# pathlab_reference_platform(out): e.g. Linux-x86_64-GNU, Darwin-arm64-AppleClang-libcxx.
function(pathlab_reference_platform out)
  set(p "${CMAKE_SYSTEM_NAME}-${CMAKE_SYSTEM_PROCESSOR}-${CMAKE_CXX_COMPILER_ID}")
  if(PATHLAB_LIBCXX OR APPLE)
    string(APPEND p "-libcxx")
  endif()
  set(${out} ${p} PARENT_SCOPE)
endfunction()

# pathlab_framework_digest(out): the framework headers a task file compiles
# against (line endings normalised: a Windows checkout may add CRs). Objects
# built against other headers could disagree with them on a struct's layout.
function(pathlab_framework_digest out)
  file(GLOB headers RELATIVE ${CMAKE_SOURCE_DIR}/framework CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/framework/*/*.h)
  list(SORT headers)
  set(all "")
  foreach(header IN LISTS headers)
    file(READ ${CMAKE_SOURCE_DIR}/framework/${header} text)
    string(REPLACE "\r\n" "\n" text "${text}")
    string(SHA256 hash "${text}")
    string(APPEND all "${header} ${hash}\n")
  endforeach()
  string(SHA256 digest "${all}")
  set(${out} ${digest} PARENT_SCOPE)
endfunction()

# The course tree: `cmake --build B --target pathlab-reference-objects` puts
# B/reference-objects/PLATFORM/ (the reference's task files, compiled as
# this build compiles them, debug sections and local symbols stripped).
function(pathlab_add_reference_objects_target)
  pathlab_reference_platform(platform)
  pathlab_framework_digest(digest)
  set(dest ${CMAKE_BINARY_DIR}/reference-objects/${platform})
  set(commands "")
  set(names "")
  foreach(n RANGE 1 ${PATHLAB_TASK_COUNT})
    set(object ${dest}/task-${n}${CMAKE_CXX_OUTPUT_EXTENSION})
    list(APPEND commands COMMAND ${CMAKE_COMMAND} -E copy $<TARGET_OBJECTS:pathlab_task${n}_reference> ${object})
    if(CMAKE_OBJCOPY AND NOT APPLE AND NOT MSVC)
      list(APPEND commands COMMAND ${CMAKE_OBJCOPY} --strip-debug --discard-all ${object})
    endif()
    list(APPEND names "\"${n}\": \"task-${n}${CMAKE_CXX_OUTPUT_EXTENSION}\"")
  endforeach()
  list(JOIN names ", " names)
  file(GENERATE OUTPUT ${dest}/manifest.json CONTENT "{
  \"platform\": \"${platform}\",
  \"compiler\": \"${CMAKE_CXX_COMPILER_ID}\",
  \"compiler_version\": \"${CMAKE_CXX_COMPILER_VERSION}\",
  \"build_type\": \"${CMAKE_BUILD_TYPE}\",
  \"framework_digest\": \"${digest}\",
  \"objects\": {${names}}
}
")
  add_custom_target(pathlab-reference-objects ${commands} COMMAND_EXPAND_LISTS VERBATIM
                    COMMENT "The reference's compiled task files in ${dest}")
  foreach(n RANGE 1 ${PATHLAB_TASK_COUNT})
    add_dependencies(pathlab-reference-objects pathlab_task${n}_reference)
  endforeach()
endfunction()

# pathlab_import_reference_objects(status): the student release's reference,
# where reference-objects/ has this platform's; `status` says what was used.
function(pathlab_import_reference_objects status)
  pathlab_reference_platform(platform)
  set(folder ${CMAKE_SOURCE_DIR}/reference-objects/${platform})
  set(why "")
  if(NOT EXISTS ${folder}/manifest.json)
    set(why "no compiled reference for ${platform} in reference-objects/")
  else()
    file(READ ${folder}/manifest.json manifest)
    string(JSON built_version GET "${manifest}" compiler_version)
    string(JSON built_digest GET "${manifest}" framework_digest)
    pathlab_framework_digest(digest)
    string(REGEX MATCH "^[0-9]+" built_major "${built_version}")
    string(REGEX MATCH "^[0-9]+" major "${CMAKE_CXX_COMPILER_VERSION}")
    if(NOT digest STREQUAL built_digest)
      set(why "the framework headers differ from those the compiled reference was built against (edited?)")
    elseif(major LESS built_major)
      set(why "the compiled reference needs ${CMAKE_CXX_COMPILER_ID} ${built_major} or newer (this is ${CMAKE_CXX_COMPILER_VERSION})")
    endif()
  endif()
  if(why)
    message(STATUS "PathLab: ${why}: the judges and candidates use your own files for every task")
    set(${status} "none: ${why}" PARENT_SCOPE)
    return()
  endif()
  foreach(n RANGE 1 ${PATHLAB_TASK_COUNT})
    string(JSON object GET "${manifest}" objects ${n})
    add_library(pathlab_task${n}_reference OBJECT IMPORTED GLOBAL)
    set_target_properties(pathlab_task${n}_reference PROPERTIES IMPORTED_OBJECTS ${folder}/${object})
  endforeach()
  message(STATUS "PathLab: the reference tasks from reference-objects/${platform} (compiled)")
  set(${status} "compiled: reference-objects/${platform}" PARENT_SCOPE)
endfunction()

# pathlab_link_tasks(TARGET <target> [VARIANT reference|student|selected]
#                    [TASK n TASK_VARIANT reference|student|selected] [FRAMEWORK library])
#   VARIANT       implementation of every task (default: selected)
#   FRAMEWORK     the framework's layers it links (default pathlab_framework: all)
#   TASK n        task n uses TASK_VARIANT instead: a suite for task n links
#                 task n as configured and every other task from the
#                 reference, so one mistake is never punished twice
#   selected      the configured choice: PATHLAB_TASKS, or PATHLAB_TASKn
#   reference     falls back to the student file in a student release
#                 (a tree without solutions/)
function(pathlab_link_tasks)
  cmake_parse_arguments(ARG "" "TARGET;VARIANT;TASK;TASK_VARIANT;FRAMEWORK" "VARIANTS" ${ARGN})
  if(NOT ARG_VARIANT)
    set(ARG_VARIANT selected)
  endif()
  if(NOT ARG_FRAMEWORK)
    set(ARG_FRAMEWORK pathlab_framework)
  endif()
  foreach(n RANGE 1 ${PATHLAB_TASK_COUNT})
    set(v ${ARG_VARIANT})
    if(ARG_TASK AND n EQUAL ARG_TASK)
      set(v ${ARG_TASK_VARIANT})
    endif()
    if(ARG_VARIANTS)  # one per task, in order
      math(EXPR i "${n} - 1")
      list(GET ARG_VARIANTS ${i} v)
    endif()
    pathlab_task_variant(${n} ${v} v)
    target_sources(${ARG_TARGET} PRIVATE $<TARGET_OBJECTS:pathlab_task${n}_${v}>)
  endforeach()
  target_link_libraries(${ARG_TARGET} PRIVATE ${ARG_FRAMEWORK})
endfunction()

# pathlab_task_variant(n requested out): the implementation task n links.
function(pathlab_task_variant n requested out)
  set(v ${requested})
  if(v STREQUAL selected)
    set(v ${PATHLAB_TASKS})
    if(NOT n IN_LIST PATHLAB_HANDED_OUT)
      set(v reference)  # not handed out in this course
    endif()
    if(PATHLAB_TASK${n})
      set(v ${PATHLAB_TASK${n}})
    endif()
  endif()
  if(NOT v MATCHES "^(reference|student)$")
    message(FATAL_ERROR "PATHLAB_TASK${n}/PATHLAB_TASKS must be 'reference' or 'student', got '${v}'")
  endif()
  if(v STREQUAL reference AND NOT TARGET pathlab_task${n}_reference)
    set(v student)  # student release: there is no reference
  endif()
  set(${out} ${v} PARENT_SCOPE)
endfunction()

# Human-readable summary of the configured choice, compiled into the binaries
# (pathlab_add_task_summary).
function(pathlab_task_summary out)
  cmake_parse_arguments(ARG "" "VARIANT" "VARIANTS" ${ARGN})
  if(NOT ARG_VARIANT)
    set(ARG_VARIANT selected)
  endif()
  set(s "")
  foreach(n RANGE 1 ${PATHLAB_TASK_COUNT})
    set(v ${ARG_VARIANT})
    if(ARG_VARIANTS)
      math(EXPR i "${n} - 1")
      list(GET ARG_VARIANTS ${i} v)
    endif()
    pathlab_task_variant(${n} ${v} v)
    string(APPEND s "${n}:${v} ")
  endforeach()
  string(STRIP "${s}" s)
  set(${out} "${s}" PARENT_SCOPE)
endfunction()

# pathlab_add_task_summary(TARGET [VARIANT v | VARIANTS v1 ... vN]):
# the program's linkedTaskSummary() (apps/task_summary.h), a one-line source
# of its own, so the sources that programs share are compiled once for every
# choice of tasks.
function(pathlab_add_task_summary target)
  pathlab_task_summary(summary ${ARGN})
  set(file ${CMAKE_BINARY_DIR}/task-summaries/${target}.cpp)
  file(CONFIGURE OUTPUT ${file} CONTENT "#include \"task_summary.h\"
const char* pathlab::linkedTaskSummary() { return \"${summary}\"; }
")
  target_sources(${target} PRIVATE ${file})
  target_include_directories(${target} PRIVATE ${CMAKE_SOURCE_DIR}/apps)
endfunction()
