// What the CLI's commands share, one phase per header (include the one you need; this header
// gathers them for the commands that use several):
//   conversion_options.h  the conversion options, their registration and translation, the cache key
//   parse_errors.h        CLI11's usage errors in the house format, "did you mean" (edit distance)
//   output_commit.h       atomic writes, all-or-nothing outputs, reports, output-is-an-input
//   source_reading.h      reading the input shaders (standard input too; the test hook)
//   diagnostic_output.h   printing diagnostics and the "N errors generated." summary
//   depfile.h             Make/Ninja depfiles, written and parsed
//   convert_command.h     the single-shader / --pipeline command (its child: conversion_child.h)
// The codec of what the CLI's processes hand each other is result_codec.h.
#pragma once

#include "cli/conversion_options.h"
#include "cli/convert_command.h"
#include "cli/depfile.h"
#include "cli/diagnostic_output.h"
#include "cli/output_commit.h"
#include "cli/parse_errors.h"
#include "cli/source_reading.h"
