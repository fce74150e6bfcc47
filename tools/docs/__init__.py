"""The documents made from the code: the write-up, the handout tables, their sections."""
