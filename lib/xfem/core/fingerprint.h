// SPDX-License-Identifier: MIT
#pragma once
#include <cstdint>
#include <map>
#include <string>

#include "xfem/core/json_io.h"
#include "xfem/core/mesh.h"

namespace xfem {

/// Stage fingerprints (docs/FORMATS.md "Fingerprints"): a 64-bit FNV-1a hash of the data a later
/// stage depends on, so that a stage can check that the files it is given belong together
/// (the cut an enriched mesh was classified with, the mesh and problem a solution was solved for)
/// instead of computing a meaningless answer. Written as "fnv1a64:" and 16 lower-case hex digits.
using Fingerprint = std::uint64_t;

/// FNV-1a 64 of raw bytes, continuing from `seed` (the FNV offset basis by default).
Fingerprint fnv1a64(const void* data, std::size_t bytes, Fingerprint seed = 0xcbf29ce484222325ULL);

/// "fnv1a64:0123456789abcdef".
std::string to_string(Fingerprint f);

/// Parses to_string's form; false if `text` is not one.
bool parse_fingerprint(const std::string& text, Fingerprint* f);

/// The geometry of a mesh: point count, coordinates (their IEEE bits), tet or triangle count and
/// point ids. Arrays are left out: a stage adds arrays but keeps the geometry.
Fingerprint fingerprint(const TetMesh& mesh);
Fingerprint fingerprint(const TriangleMesh& mesh);

/// A JSON document's content, independent of white space and number spelling (its compact dump).
Fingerprint fingerprint(const Json& j);

/// A JSON file's content as fingerprint(Json); throws xfem::Error as read_json does.
Fingerprint fingerprint_json_file(const std::string& path);

/// The VTK field array that carries a fingerprint: two Int64 values, the high and low 32 bits
/// (field arrays hold doubles, exact below 2^53 only). Names in use: "cut_fingerprint" (the cut
/// xfem-classify classified with).
void store_fingerprint(DataArrays& field_data, const std::string& name, Fingerprint f);

/// The fingerprint stored under `name`, or false when the file has none (written before
/// fingerprints existed, or made by another program): then nothing can be checked.
bool stored_fingerprint(const DataArrays& field_data, const std::string& name, Fingerprint* f);

/// Checks that `cut` (read from `cut_path`) is the cut `mesh` (read from `mesh_path`) was
/// classified with. Throws "<cut_path>: not the cut <mesh_path> was classified with (...)".
/// A mesh without the record passes.
void check_cut_matches(const TetMesh& mesh, const std::string& mesh_path, const TriangleMesh& cut,
                       const std::string& cut_path);

/// What a solution (u.mtx) or a system records about its inputs, as "name fnv1a64:..." pairs,
/// e.g. {"enriched": ..., "cut": ..., "problem": ...}. Written as Matrix Market comment lines
/// "% xfem-fingerprint <name> fnv1a64:<hex>" and as the JSON object "fingerprints".
using Provenance = std::map<std::string, Fingerprint>;

Json provenance_json(const Provenance& p);
/// Reads the "fingerprints" object of a JSON document (empty if there is none); `file` for errors.
Provenance provenance_from_json(const Json& j, const std::string& file);
/// The comment lines for a Matrix Market file (without the trailing newline).
std::vector<std::string> provenance_comments(const Provenance& p);
/// The "% xfem-fingerprint" lines of a Matrix Market file's header (empty if none). Throws
/// "<path>: malformed fingerprint line '...'" for a line that is not "<name> fnv1a64:<hex>" and
/// "<path>: conflicting fingerprint lines for '<name>' (...)" for a name given two values.
Provenance read_mtx_provenance(const std::string& path);

/// Throws "<file>: made for <what> <expected_file> ... but given <given_file>" when `recorded`
/// has `name` and it differs from `actual`. Nothing is checked when `recorded` lacks `name`.
void check_provenance(const Provenance& recorded, const std::string& file, const std::string& name,
                      Fingerprint actual, const std::string& given_file);

}  // namespace xfem
