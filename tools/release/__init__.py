"""What a course hands out: the packaged tree, the student release's platforms, a course's own task."""
