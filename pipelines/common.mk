# Shared by every pipeline: where the tools are, how chatty they are, and make's safety nets.
# BIN: the built tools (Makefile.examples passes its own); QUIET: -q for quiet runs, empty to see progress.
PIPELINES_DIR := $(dir $(lastword $(MAKEFILE_LIST)))
BIN ?= $(abspath $(PIPELINES_DIR)/../build/tools)
QUIET ?= -q
# Headless PNG rendering needs an X server: xvfb-run provides one when there is no display.
XVFB ?= $(if $(DISPLAY),,xvfb-run -a)
# A failed command leaves no target behind, so the next make reruns it.
.DELETE_ON_ERROR:
