/* pathlab-autolab-grade: the grader's way to root inside PathLab's Autolab image.
 *
 * Autolab's Tango runs each job's `make` as the unprivileged user
 * "autograde" (its setuid-root autodriver drops to it). There tools/grade
 * could not run the student's code as a uid of its own, and the candidate
 * would share the grader's uid. Installed setuid root in the image
 * (tools/autolab/image-setup), this program gives the grader root, as
 * Gradescope's container does, and nothing else: it runs one fixed program,
 * tools/autolab/grade-job of the image's tree, with a clean environment and
 * Python's isolated mode; the job's Makefile passes the arguments, which
 * grade-job checks. The student's code never calls it: tools/grade runs it
 * as the sandbox uid under no_new_privs, where a setuid bit does nothing.
 *
 * Built with -DPATHLAB_ROOT="\"/opt/pathlab\"" (the tree, as the image has it). */
#define _GNU_SOURCE
#include <grp.h>
#include <stdio.h>
#include <unistd.h>

#ifndef PATHLAB_ROOT
#error "build with -DPATHLAB_ROOT=\"\\\"/path/of/the/tree\\\"\""
#endif

enum { kMaxArguments = 16 };

int main(int argc, char** argv) {
  if (argc > kMaxArguments) {
    fprintf(stderr, "pathlab-autolab-grade: at most %d arguments\n", kMaxArguments);
    return 2;
  }
  if (setgroups(0, NULL) != 0 || setresgid(0, 0, 0) != 0 || setresuid(0, 0, 0) != 0) {
    perror("pathlab-autolab-grade: cannot become root (is it installed setuid root?)");
    return 2;
  }
  char* arguments[kMaxArguments + 4] = {"python3", "-I", PATHLAB_ROOT "/tools/autolab/grade-job"};
  for (int i = 1; i < argc; ++i) arguments[i + 2] = argv[i];
  arguments[argc + 2] = NULL;
  char* environment[] = {"PATH=/usr/local/bin:/usr/bin:/bin", "LANG=C.UTF-8", "HOME=/root", NULL};
  execve("/usr/bin/python3", arguments, environment);
  perror("pathlab-autolab-grade: cannot run /usr/bin/python3");
  return 2;
}
