// SPDX-License-Identifier: MIT
#pragma once
#include <string>

namespace xfem {

/// Checks a VTK XML file (.vtu, .vtp) before VTK 9.1's reader sees it. That reader divides by a
/// zero block size (SIGFPE) and allocates whatever a count attribute or a binary array's header
/// claims. So the start tags are read as the XML parser reads them, and every count attribute
/// (NumberOfPoints, NumberOfCells, NumberOfComponents, ...), every tuple count times component
/// count, and every binary array's header (appended raw or base64, inline base64; compressed or
/// not; either byte order and header type) is checked against the file's size. Throws xfem::Error
/// "<path>: <what> (corrupt file?)". Accepts whatever VTK's writers produce.
void check_vtk_xml_sizes(const std::string& path);

/// The same for a file's text already read (standard input); `name` is shown in the error.
void check_vtk_xml_text(const std::string& name, const std::string& text);

}  // namespace xfem
