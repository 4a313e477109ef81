#pragma once
// Independent readers run as subprocesses: Debian's meshio (/usr/bin/python3) and gmsh. Tests
// that use them skip when they are not installed.
#include <cstdio>
#include <cstdlib>
#include <string>

namespace riemesh::test {

/// Standard output of a shell command (stderr discarded).
inline std::string run_capture(const std::string& command) {
  std::FILE* pipe = popen((command + " 2>/dev/null").c_str(), "r");
  if (!pipe) return "popen failed";
  std::string out;
  char buffer[512];
  while (std::fgets(buffer, sizeof buffer, pipe)) out += buffer;
  pclose(pipe);
  return out;
}

inline bool meshio_available() {
  return std::system("/usr/bin/python3 -c 'import meshio' >/dev/null 2>&1") == 0;
}

inline bool gmsh_available() { return std::system("gmsh --version >/dev/null 2>&1") == 0; }

/// What meshio reads from a file: "<points> type:count... | data: name:sorted distinct values".
/// Cell data arrays (gmsh:physical, ref, dim) give their distinct values per cell block;
/// point data their names and widths.
inline std::string meshio_summary(const std::string& path) {
  // Double quotes only: the script goes inside a single-quoted shell argument.
  static const char kScript[] =
      "import sys, meshio, numpy as np\n"
      "m = meshio.read(sys.argv[1])\n"
      "out = [str(len(m.points))]\n"
      "out += [\"%s:%d\" % (c.type, len(c.data)) for c in m.cells]\n"
      "for name in sorted(m.cell_data):\n"
      "    if name == \"gmsh:geometrical\": continue\n"
      "    for c, d in zip(m.cells, m.cell_data[name]):\n"
      "        out.append(\"%s[%s]=%s\" % (name, c.type,\n"
      "                   \",\".join(str(int(v)) for v in np.unique(d))))\n"
      "for name in sorted(m.point_data):\n"
      "    if name.startswith(\"gmsh:\"): continue\n"
      "    d = np.asarray(m.point_data[name]).reshape(len(m.points), -1)\n"
      "    out.append(\"point:%s:%d\" % (name, d.shape[1]))\n"
      "print(\" \".join(out))\n";
  std::string command = "/usr/bin/python3 -c '";
  command += kScript;
  command += "' '";
  command += path;
  command += "'";
  std::string out = run_capture(command);
  // The last line: meshio may print blank lines or notes before.
  while (!out.empty() && (out.back() == '\n' || out.back() == ' ')) out.pop_back();
  const std::size_t eol = out.rfind('\n');
  return eol == std::string::npos ? out : out.substr(eol + 1);
}

}  // namespace riemesh::test
