"""Prints without end and never drives."""
import sys

line = "spam " * 200 + "\n"
while True:
    sys.stdout.write(line)
