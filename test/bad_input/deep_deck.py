#!/usr/bin/env python3
"""Writes a deck nested DEPTH ParameterLists deep (argv: path depth), for the reader's bound."""
import sys

path, depth = sys.argv[1], int(sys.argv[2])
with open(path, "w") as f:
    f.write('<ParameterList name="impm">' + '<ParameterList name="a">' * depth +
            "</ParameterList>" * (depth + 1) + "\n")
