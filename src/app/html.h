/// \file
/// Text made safe for HTML, shared by the batch report and the golden-image report.
#pragma once

#include <string>

namespace rb {

/// Text made safe inside HTML elements and attribute values: & < > " ' become entities.
inline std::string escapeHtml(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (const char c : text) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            case '\'':
                out += "&#39;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

}  // namespace rb
