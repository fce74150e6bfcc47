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
endfunction()

# pathlab_link_tasks(TARGET <target> [VARIANT reference|student|selected]
#                    [TASK n TASK_VARIANT reference|student|selected])
#   VARIANT       implementation of every task (default: selected)
#   TASK n        task n uses TASK_VARIANT instead: a suite for task n links
#                 task n as configured and every other task from the
#                 reference, so one mistake is never punished twice
#   selected      the configured choice: PATHLAB_TASKS, or PATHLAB_TASKn
#   reference     falls back to the student file in a student release
#                 (a tree without solutions/)
function(pathlab_link_tasks)
  cmake_parse_arguments(ARG "" "TARGET;VARIANT;TASK;TASK_VARIANT" "" ${ARGN})
  if(NOT ARG_VARIANT)
    set(ARG_VARIANT selected)
  endif()
  foreach(n RANGE 1 ${PATHLAB_TASK_COUNT})
    set(v ${ARG_VARIANT})
    if(ARG_TASK AND n EQUAL ARG_TASK)
      set(v ${ARG_TASK_VARIANT})
    endif()
    pathlab_task_variant(${n} ${v} v)
    target_sources(${ARG_TARGET} PRIVATE $<TARGET_OBJECTS:pathlab_task${n}_${v}>)
  endforeach()
  target_link_libraries(${ARG_TARGET} PRIVATE pathlab_framework)
endfunction()

# pathlab_task_variant(n requested out): the implementation task n links.
function(pathlab_task_variant n requested out)
  set(v ${requested})
  if(v STREQUAL selected)
    set(v ${PATHLAB_TASKS})
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

# Human-readable summary of the configured choice, compiled into the binaries.
function(pathlab_task_summary out)
  cmake_parse_arguments(ARG "" "VARIANT" "" ${ARGN})
  if(NOT ARG_VARIANT)
    set(ARG_VARIANT selected)
  endif()
  set(s "")
  foreach(n RANGE 1 ${PATHLAB_TASK_COUNT})
    pathlab_task_variant(${n} ${ARG_VARIANT} v)
    string(APPEND s "${n}:${v} ")
  endforeach()
  string(STRIP "${s}" s)
  set(${out} "${s}" PARENT_SCOPE)
endfunction()
