# Sourced by tests/cli/test_cli.sh and tests/gui/test_gui.sh, with $root (the
# repository) and $build (the build folder) set.
# Which student files the build compiled (cmake/PathLabTasks.cmake's lookup:
# PATHLAB_STUDENT_DIR as the tasks/ tree or flat, else tasks/), and which of
# them are undone: a PATHLAB_TODO call left outside comments.
# The task list is the folders tasks/NN-name/ (cmake/PathLabTasks.cmake);
# task NN's file is NN-name/name.cpp, the name's dashes as underscores.
task_paths=()
for folder in "$root"/tasks/[0-9][0-9]-*/; do
  folder=$(basename "$folder") stem=${folder#[0-9][0-9]-}
  task_paths+=("$folder/${stem//-/_}.cpp")
done
task_count=${#task_paths[@]}
student_dir=$(sed -n 's/^PATHLAB_STUDENT_DIR:PATH=//p' "$build/CMakeCache.txt" 2>/dev/null)
student_dir=${student_dir:-$root/tasks}
task_file() {  # task_file N
  local rel=${task_paths[$1 - 1]} f
  for f in "$student_dir/$rel" "$student_dir/${rel#*/}" "$root/tasks/$rel"; do
    [[ -f $f ]] && { realpath "$f"; return; }
  done
}
task_undone() { grep -v '^[[:space:]]*//' "$(task_file "$1")" | grep -q 'PATHLAB_TODO('; }
shown_as() { local f; f=$(task_file "$1"); echo "${f#"$root"/}"; }  # as __FILE__ names it
