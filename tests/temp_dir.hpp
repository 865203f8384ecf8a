#pragma once
// A fresh directory for one test, removed with everything in it afterwards.
#include <atomic>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <string_view>

struct TempDir {
  std::filesystem::path path;

  TempDir() {
    static std::atomic<int> counter = 0;
    path = std::filesystem::temp_directory_path() /
           ("sweetspot_test_" + std::to_string(std::random_device{}()) + "_" + std::to_string(counter++));
    std::filesystem::create_directories(path);
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  std::filesystem::path write(const std::string& name, std::string_view text) const {
    std::ofstream(path / name, std::ios::binary) << text;
    return path / name;
  }
  std::string operator/(const std::string& name) const { return (path / name).string(); }
};
