#include "core/ColourClassesYaml.h"

#include "core/YamlText.h"

#include <array>
#include <sstream>

namespace omnitune {

namespace {

// The classes configs had before colors.classes, in their old order (the defaults' first six).
constexpr std::array<const char*, 6> kOldClassSections = {"black", "white", "green", "orange", "cyan", "magenta"};

struct Reader {
    const std::string& text;
    const std::string& file;
    ColourClassesRead& out;

    bool fail(ConfigIssueKind kind, const std::string& key, const std::string& message)
    {
        if (!out.error) out.error = ConfigIssue{kind, file, yamlLineOfKey(text, "colors.classes"), key, message};
        return false;
    }
    void warn(ConfigIssueKind kind, const std::string& key, const std::string& message)
    {
        out.warnings.push_back(ConfigIssue{kind, file, 0, key, message});
    }
    static bool present(const cv::FileNode& n) { return !n.empty() && !n.isNone(); }

    bool readInt(const cv::FileNode& n, const std::string& key, int& v)
    {
        if (!n.isInt()) return fail(ConfigIssueKind::WrongType, key, "expected an integer, found " + yamlTypeOf(n));
        v = int(n);
        return true;
    }
    bool readBool(const cv::FileNode& n, const std::string& key, bool& v)
    {
        if (n.isInt() && (int(n) == 0 || int(n) == 1)) {
            v = int(n) == 1;
            return true;
        }
        if (n.isString() && (std::string(n) == "true" || std::string(n) == "false")) {
            v = std::string(n) == "true";
            return true;
        }
        return fail(ConfigIssueKind::WrongType, key, "expected 0/1 or true/false, found " + yamlTypeOf(n));
    }
    bool readString(const cv::FileNode& n, const std::string& key, std::string& v)
    {
        if (!n.isString()) return fail(ConfigIssueKind::WrongType, key, "expected text, found " + yamlTypeOf(n));
        v = std::string(n);
        return true;
    }
    // A list of exactly `count` integers in 0..`max`.
    bool readInts(const cv::FileNode& n, const std::string& key, int count, int max, int* v)
    {
        if (!n.isSeq() || int(n.size()) != count)
            return fail(ConfigIssueKind::WrongType, key,
                        "expected a list of " + std::to_string(count) + " integers, found " + yamlTypeOf(n));
        for (int i = 0; i < count; ++i) {
            const cv::FileNode e = n[i];
            if (!e.isInt()) return fail(ConfigIssueKind::WrongType, key, "expected integers, found " + yamlTypeOf(e) + " in it");
            v[i] = int(e);
            if (v[i] < 0 || v[i] > max)
                return fail(ConfigIssueKind::OutOfRange, key, std::to_string(v[i]) + " is outside 0.." + std::to_string(max));
        }
        return true;
    }
    void unknownKeys(const cv::FileNode& map, const std::string& key, std::initializer_list<const char*> known)
    {
        for (const cv::FileNode& child : map) {
            bool ok = false;
            for (const char* k : known) ok = ok || child.name() == k;
            if (!ok) warn(ConfigIssueKind::UnknownKey, key + "." + child.name(), "unknown key, ignored (a typo?)");
        }
    }

    bool readBox(const cv::FileNode& n, const std::string& key, HsvRange& box)
    {
        if (!n.isMap()) return fail(ConfigIssueKind::WrongType, key, "expected a box {h: [min, max], s: [...], v: [...]}, found " + yamlTypeOf(n));
        int h[2], s[2], v[2];
        for (const char* part : {"h", "s", "v"})
            if (!present(n[part])) return fail(ConfigIssueKind::MissingKey, key + "." + part, "the box has no " + std::string(part) + " range");
        if (!readInts(n["h"], key + ".h", 2, 179, h) || !readInts(n["s"], key + ".s", 2, 255, s) ||
            !readInts(n["v"], key + ".v", 2, 255, v))
            return false;
        box = HsvRange{true, h[0], h[1], s[0], s[1], v[0], v[1]};
        if (present(n["enabled"]) && !readBool(n["enabled"], key + ".enabled", box.enabled)) return false;
        unknownKeys(n, key, {"h", "s", "v", "enabled"});
        return true;
    }

    bool readClass(const cv::FileNode& n, const std::string& key, ColourClassDef& c)
    {
        if (!n.isMap()) return fail(ConfigIssueKind::WrongType, key, "expected a class (name, role, display, boxes), found " + yamlTypeOf(n));
        for (const char* part : {"name", "role", "boxes"})
            if (!present(n[part])) return fail(ConfigIssueKind::MissingKey, key + "." + part, "the class has no " + std::string(part));
        if (!readString(n["name"], key + ".name", c.name)) return false;
        std::string role;
        if (!readString(n["role"], key + ".role", role)) return false;
        const auto parsed = parseColourRole(role);
        if (!parsed)
            return fail(ConfigIssueKind::BadValue, key + ".role",
                        "\"" + role + "\" is no role: field, line, black, ball, marker or other");
        c.role = *parsed;
        if (present(n["display"])) {
            int bgr[3];
            if (!readInts(n["display"], key + ".display", 3, 255, bgr)) return false;
            c.display = {std::uint8_t(bgr[0]), std::uint8_t(bgr[1]), std::uint8_t(bgr[2])};
        }
        if (present(n["enabled"]) && !readBool(n["enabled"], key + ".enabled", c.enabled)) return false;
        const cv::FileNode boxes = n["boxes"];
        if (!boxes.isSeq()) return fail(ConfigIssueKind::WrongType, key + ".boxes", "expected a list of boxes, found " + yamlTypeOf(boxes));
        for (int j = 0; j < int(boxes.size()); ++j) {
            HsvRange box;
            if (!readBox(boxes[j], key + ".boxes[" + std::to_string(j) + "]", box)) return false;
            c.boxes.push_back(box);
        }
        unknownKeys(n, key, {"name", "role", "display", "enabled", "boxes"});
        return true;
    }

    void readList(const cv::FileNode& list)
    {
        if (!list.isSeq()) {
            fail(ConfigIssueKind::WrongType, "colors.classes", "expected a list of classes, found " + yamlTypeOf(list));
            return;
        }
        // More than kMaxColourClasses are read, and refused by checkColourClasses with the count.
        out.classes.clear();
        for (int i = 0; i < int(list.size()); ++i) {
            ColourClassDef c;
            if (!readClass(list[i], "colors.classes[" + std::to_string(i) + "]", c)) return;
            out.classes.push_back(std::move(c));
        }
    }

    // The old form: one section of scalar keys per fixed class; missing keys keep the defaults.
    void readOld(const cv::FileNode& colors)
    {
        out.oldForm = true;
        out.classes = defaultColourClasses();
        for (std::size_t i = 0; i < kOldClassSections.size(); ++i) {
            ColourClassDef& c = out.classes[i];
            HsvRange& box = c.boxes.front();
            const std::string key = std::string("colors.") + kOldClassSections[i];
            const cv::FileNode section = colors[kOldClassSections[i]];
            const std::pair<const char*, int*> ints[] = {{"h_min", &box.hMin}, {"h_max", &box.hMax}, {"s_min", &box.sMin},
                                                         {"s_max", &box.sMax}, {"v_min", &box.vMin}, {"v_max", &box.vMax}};
            if (!present(section) || !section.isMap()) {
                if (present(section))
                    fail(ConfigIssueKind::WrongType, key, "expected a section, found " + yamlTypeOf(section));
                else
                    warn(ConfigIssueKind::MissingKey, key, "missing, using the default class");
                continue;
            }
            if (present(section["enabled"]) && !readBool(section["enabled"], key + ".enabled", c.enabled)) return;
            for (const auto& [name, field] : ints) {
                if (!present(section[name])) {
                    warn(ConfigIssueKind::MissingKey, key + "." + name, "missing, using the default " + std::to_string(*field));
                    continue;
                }
                if (!readInt(section[name], key + "." + name, *field)) return;
            }
            unknownKeys(section, key, {"enabled", "h_min", "h_max", "s_min", "s_max", "v_min", "v_max"});
        }
        warn(ConfigIssueKind::OldForm, "colors",
             "colour classes in the old per-class keys (colors.green.h_min ...), read as before; "
             "omnitune-config --upgrade FILE rewrites them as the list colors.classes");
    }
};

std::string range(int a, int b) { return "[ " + std::to_string(a) + ", " + std::to_string(b) + " ]"; }

}  // namespace

ColourClassesRead readColourClasses(const cv::FileNode& colors, const std::string& text, const std::string& fileName)
{
    ColourClassesRead out;
    Reader r{text, fileName, out};
    const bool mapped = !colors.empty() && colors.isMap();
    if (mapped && Reader::present(colors["classes"])) {
        r.readList(colors["classes"]);
        return out;
    }
    bool old = false;
    for (const char* name : kOldClassSections) old = old || (mapped && Reader::present(colors[name]));
    if (old)
        r.readOld(colors);
    else
        r.warn(ConfigIssueKind::MissingKey, "colors.classes", "missing, using the default classes");
    return out;
}

bool isColourClassesPath(const std::string& path, bool oldForm)
{
    if (path == "colors.classes") return true;
    if (!oldForm) return false;
    for (const char* name : kOldClassSections)
        if (path == std::string("colors.") + name) return true;
    return false;
}

std::string writeColourClasses(const ColourClasses& classes, const std::string& indent)
{
    const std::string item = indent + "   ";
    std::ostringstream out;
    out << indent << "#  Colour classes in priority order: a pixel takes the first class with a box holding its colour.\n"
        << indent << "#  role: field | line | black | ball | marker | other; display: BGR; hue min above max wraps through 0\n"
        << indent << "classes:\n";
    for (const ColourClassDef& c : classes) {
        out << item << "- name: \"" << c.name << "\"\n"
            << item << "  role: " << colourRoleName(c.role) << "\n"
            << item << "  display: [ " << int(c.display[0]) << ", " << int(c.display[1]) << ", " << int(c.display[2]) << " ]\n"
            << item << "  enabled: " << (c.enabled ? 1 : 0) << "\n"
            << item << "  boxes:\n";
        for (const HsvRange& b : c.boxes)
            out << item << "     - { h: " << range(b.hMin, b.hMax) << ", s: " << range(b.sMin, b.sMax) << ", v: "
                << range(b.vMin, b.vMax) << (b.enabled ? "" : ", enabled: 0") << " }\n";
    }
    return out.str();
}

std::string colourClassesMarkdown()
{
    std::ostringstream md;
    md << "\n### colors.classes\n\n"
       << "The colour classes, a list in priority order: a pixel takes the first enabled class with a box that\n"
       << "holds its colour, else it is `unknown`. HSV in OpenCV's 8-bit scale (H 0..179, S and V 0..255); a hue\n"
       << "range whose min is above its max wraps through 0 (red: `h: [170, 10]`). What the detector does with a\n"
       << "class follows from its `role`, never from its name:\n\n"
       << "- `field`: the carpet: white in the green / non-green image Canny sees, \"green\" in the non-green test,\n"
       << "  the carpet's brightness for relative black; several classes may be field (a cyan-green and a dark-green region)\n"
       << "- `line`: field lines, `edges.white_level` in the binary image\n"
       << "- `black`: robots and shadows, the non-black test; with `black_relative` the first black class takes every\n"
       << "  pixel darker than `black_v_ratio` x the carpet's median V\n"
       << "- `ball`: a ball colour; `validation.ball_hint_class` may name one\n"
       << "- `marker`: team markers\n"
       << "- `other`: shown in the segmented pane only\n\n"
       << "Each class: `name` (unique; a-z first, then a-z, 0-9, `_`; not `unknown` or `none`), `role`, `display`\n"
       << "(BGR in the segmented pane), `enabled` (optional, default 1) and `boxes` (at least one; the class is\n"
       << "their union; a box may say `enabled: 0`). At most " << kMaxColourClasses
       << " classes (the segmented image stores class ids 1..15,\n"
       << "0 = unknown). Refused at load, with the key named: a class with no box, an empty box (S or V min above\n"
       << "max), a bound outside its scale, a duplicate or malformed name, an unknown role, more than "
       << kMaxColourClasses << " classes,\n"
       << "no enabled field class.\n\n"
       << "Configs from before the list (`colors.green.h_min`, ... one section per fixed class) still load, as\n"
       << "before, with a warning; `omnitune-config --upgrade FILE` rewrites them in this form, unchanged in meaning.\n\n"
       << "The defaults (`omnitune-config --defaults` writes them): the thesis' classes and ranges, and a yellow\n"
       << "ball class that is off, so that the default segmentation is the thesis' one.\n\n"
       << "```yaml\ncolors:\n" << writeColourClasses(defaultColourClasses(), "   ") << "```\n";
    return md.str();
}

}  // namespace omnitune
