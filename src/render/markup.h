#pragma once
/// \file
/// Text made safe inside SVG and HTML, which every page and picture writes
/// from the case's own words (file names, details, legends).
#include <string>

namespace mfz {

/// `text` inside an element or a quoted attribute: & < > " escaped, control
/// characters other than newline and tab dropped (XML allows none).
std::string markup_escaped(const std::string& text);

/// JSON inside a <script> element: "</" would end the element early.
std::string script_safe(std::string json);

}  // namespace mfz
