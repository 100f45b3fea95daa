#pragma once
/// \file
/// A case as one self-contained HTML file: the same model as the SVG, drawn
/// on a canvas per run by a small script of the project's own (inlined, so
/// nothing loads from the network), which the reader rotates by dragging and
/// zooms with the wheel; the SVG follows as the static picture.
#include <string>
#include <vector>

#include "render/case_picture.h"

namespace mfz {

class Json;

/// The HTML page of a case's runs (one, or a relation finding's two).
std::string html_case_view(const std::vector<CasePicture>& runs, const std::string& title);

/// The runs as JSON, as the viewer script reads them.
void pictures_json(Json& json, const std::vector<CasePicture>& runs);

/// The viewer script and the page's error trap, for pages that embed views
/// (the run report).
const std::string& case_viewer_script();

/// The page's error trap, first in its <head>: any script error, before or
/// after the viewer ran, is recorded on <html> as data-script-error.
const std::string& error_trap_script();

}  // namespace mfz
