#pragma once
// Where a command will write, checked before any work: a path it cannot write is refused at once
// (not after hours of computing), and no output may be one of the run's own inputs.
#include <filesystem>
#include <vector>

#include "sweetspot/study/study.hpp"

namespace sweetspot {

// The files a study's results are read from: the study file, every bat file and the profile
// each bat file names, in that order (bats in the study's bat order).
std::vector<std::filesystem::path> study_inputs(const Study& study);

// Throws InputError (one line: the path, what is wrong, what was expected) when `output` cannot
// or must not be written: an empty path; an existing directory or other non-regular file; a
// parent directory that is missing, not a directory or not writable. `beside` are the files the
// command writes next to `output` (temporary file, journal, lock): each must be absent or a
// regular file. Neither `output` nor any of `beside` may be one of `inputs`: the files
// themselves are compared (device and inode, through links), not their spelling.
void check_output_paths(const std::filesystem::path& output, const std::vector<std::filesystem::path>& beside,
                        const std::vector<std::filesystem::path>& inputs);

}  // namespace sweetspot
