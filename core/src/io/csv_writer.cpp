#include "mocap/io/csv_writer.h"

#include "mocap/base/error.h"
#include "mocap/base/number_text.h"
#include "mocap/model/sample_rows.h"
#include "mocap/base/file_io.h"

#include <charconv>
#include <cstdint>
#include <limits>

namespace mocap {

void appendCsvField(std::string& out, const std::string& field)
{
  if (field.find_first_of(",\"\r\n") == std::string::npos) {
    out += field;
    return;
  }
  out += '"';
  for (char c : field) {
    if (c == '"')
      out += '"';
    out += c;
  }
  out += '"';
}

std::string formatCsv(const Take& take)
{
  std::string out;
  out += "Frame,Time";
  for (const std::string& label : take.labels()) {
    for (const char* axis : {":X", ":Y", ":Z"}) {
      out += ',';
      appendCsvField(out, label + axis);
    }
  }
  out += '\n';

  appendSampleRows(out, take, ',');
  return out;
}

void writeCsv(const Take& take, const std::filesystem::path& path)
{
  writeFileAtomically(path, formatCsv(take));
}

} // namespace mocap
