#pragma once
// Whole files as bytes, for tests that damage or inspect what was written.
#include <fstream>
#include <sstream>
#include <string>

namespace filetest {

inline std::string readFile(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

inline void writeFile(const std::string& path, const std::string& bytes)
{
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << bytes;
}

}  // namespace filetest
