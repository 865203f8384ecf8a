#pragma once
// sweetspot certify --uncertainty U.toml: a certification under scatter. U.toml is an
// uncertainty study of model "certification" (docs/uncertainty.md); its samples run on this
// process's OpenMP threads, and what is printed is the probability of passing each rule with
// its interval and the measure's mean, standard deviation and quantiles with theirs.
#include <string>

namespace sweetspot::app {

// `output`: where the dataset goes ("" : a temporary folder, removed afterwards). Throws
// InputError (one line) for a bad file or a study of another model.
void certify_under_uncertainty(const std::string& file, const std::string& output, bool json);

}  // namespace sweetspot::app
