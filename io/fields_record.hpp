// The reduced fields.h5 of a campaign record (docs/study.md, "Campaign records"): what the
// study and trade tables compare, small enough to commit. It keeps fields.h5's layout
// (docs/fields.md, section 8) so that every reader of fields.h5 reads it, with
// - the root, /grid (x, y, x_nodes, y_nodes and its attributes; not the [ny+1, nx+1, 2]
//   nodes), /lines, /front, /profile,
//   /upstream, /summary and /obstacle as they are;
// - of /fields only the named ones, as float32 (masked as uint8), chunked and deflated;
// - no /vectors (virtual datasets of fields the record may not keep);
// - on the root @granshock_record = 1 and @record_fields (the kept names, comma-separated).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace granshock {

// The fields a record keeps unless told otherwise: those the trade table compares (phi, T,
// Ma, with mean_count and masked for its mask) and the mean velocity (ux, uy) for the
// maps' stream lines. About 80 kB each on a paper case's 167 x 167 bins.
const std::vector<std::string>& default_record_fields();

// Writes `record` (atomically) from the fields file `fields_h5`; a field named but absent
// is skipped. Throws UserError naming the file that could not be read or written.
void write_fields_record(const std::filesystem::path& fields_h5,
                         const std::filesystem::path& record,
                         const std::vector<std::string>& fields = default_record_fields());

}  // namespace granshock
