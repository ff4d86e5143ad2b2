// SPDX-License-Identifier: Zlib
#include "JsonSchema.h"

#include <algorithm>
#include <regex>
#include <set>
#include <stdexcept>

namespace btfracture::test {

using Json = nlohmann::json;

namespace {

const std::set<std::string> kAnnotations = {"$schema", "$id", "$defs", "title", "description"};
const std::set<std::string> kKeywords = {"$ref",
                                         "type",
                                         "properties",
                                         "required",
                                         "additionalProperties",
                                         "items",
                                         "minItems",
                                         "maxItems",
                                         "uniqueItems",
                                         "enum",
                                         "const",
                                         "minimum",
                                         "maximum",
                                         "exclusiveMinimum",
                                         "exclusiveMaximum",
                                         "minLength",
                                         "pattern",
                                         "oneOf",
                                         "anyOf"};

std::string child(const std::string& path, const std::string& key) {
    return path.empty() ? key : path + "." + key;
}

std::string shown(const Json& value) {
    std::string text = value.dump();
    return text.size() > 40 ? text.substr(0, 37) + "..." : text;
}

bool hasType(const Json& value, const std::string& type) {
    if (type == "object") return value.is_object();
    if (type == "array") return value.is_array();
    if (type == "string") return value.is_string();
    if (type == "boolean") return value.is_boolean();
    if (type == "null") return value.is_null();
    if (type == "number") return value.is_number();
    if (type == "integer") return value.is_number_integer();  // as the scene parser: 2.0 is not an integer
    throw std::runtime_error("schema: unknown type \"" + type + "\"");
}

}  // namespace

// Whether `value` is of the kind `schema` describes at all (its type, or the type of its enum or
// const values): a oneOf / anyOf branch of another kind explains a mismatch worse than one of the
// right kind.
bool JsonSchema::sameKind(const Json& schema, const Json& value) const {
    if (!schema.is_object()) return true;
    if (schema.contains("$ref")) return sameKind(resolve(schema), value);
    if (schema.contains("type")) {
        const Json& type = schema["type"];
        for (const Json& t : type.is_array() ? type : Json::array({type}))
            if (hasType(value, t.get<std::string>())) return true;
        return false;
    }
    if (schema.contains("const")) return schema["const"].type() == value.type();
    if (schema.contains("enum"))
        for (const Json& option : schema["enum"])
            if (option.type() == value.type()) return true;
    return !schema.contains("enum");
}

JsonSchema::JsonSchema(Json schema) : root_(std::move(schema)) {
    requireKnownKeywords(root_);
}

void JsonSchema::requireKnownKeywords(const Json& schema) const {
    if (schema.is_boolean()) return;
    if (!schema.is_object())
        throw std::runtime_error("schema: a schema must be an object, got " + shown(schema));
    for (const auto& [key, value] : schema.items()) {
        if (!kKeywords.count(key) && !kAnnotations.count(key))
            throw std::runtime_error("schema: keyword \"" + key + "\" is outside the validator's subset");
        if (key == "$defs" || key == "properties")
            for (const auto& item : value.items()) requireKnownKeywords(item.value());
        if (key == "items" || key == "additionalProperties") requireKnownKeywords(value);
        if (key == "oneOf" || key == "anyOf")
            for (const Json& branch : value) requireKnownKeywords(branch);
        if (key == "$ref") resolve(schema);
    }
}

const Json& JsonSchema::definition(const std::string& name) const {
    const auto defs = root_.find("$defs");
    if (defs == root_.end() || !defs->contains(name))
        throw std::runtime_error("schema: no definition \"" + name + "\"");
    return (*defs)[name];
}

const Json& JsonSchema::resolve(const Json& schema) const {
    const std::string ref = schema["$ref"].get<std::string>();
    const std::string prefix = "#/$defs/";
    if (ref.rfind(prefix, 0) != 0) throw std::runtime_error("schema: unsupported $ref \"" + ref + "\"");
    return definition(ref.substr(prefix.size()));
}

std::vector<std::string> JsonSchema::validate(const Json& instance) const {
    std::vector<std::string> problems;
    check(root_, instance, "", problems);
    return problems;
}

void JsonSchema::check(const Json& schema, const Json& value, const std::string& path,
                       std::vector<std::string>& problems) const {
    const std::string at = path.empty() ? "(root)" : path;
    auto fail = [&](const std::string& what) { problems.push_back(at + ": " + what); };
    if (schema.is_boolean()) {
        if (!schema.get<bool>()) fail("not allowed here");
        return;
    }
    if (schema.contains("$ref")) check(resolve(schema), value, path, problems);
    if (schema.contains("type")) {
        const Json& type = schema["type"];
        const std::vector<std::string> types = type.is_array()
                                                   ? type.get<std::vector<std::string>>()
                                                   : std::vector<std::string>{type.get<std::string>()};
        if (std::none_of(types.begin(), types.end(),
                         [&](const std::string& t) { return hasType(value, t); })) {
            fail("expected " + type.dump() + ", got " + shown(value));
            return;
        }
    }
    if (schema.contains("enum")) {
        const Json& options = schema["enum"];
        if (std::find(options.begin(), options.end(), value) == options.end())
            fail("expected one of " + options.dump() + ", got " + shown(value));
    }
    if (schema.contains("const") && value != schema["const"])
        fail("expected " + schema["const"].dump() + ", got " + shown(value));
    if (value.is_number()) {
        const double x = value.get<double>();
        if (schema.contains("minimum") && !(x >= schema["minimum"].get<double>()))
            fail("expected >= " + schema["minimum"].dump() + ", got " + shown(value));
        if (schema.contains("maximum") && !(x <= schema["maximum"].get<double>()))
            fail("expected <= " + schema["maximum"].dump() + ", got " + shown(value));
        if (schema.contains("exclusiveMinimum") && !(x > schema["exclusiveMinimum"].get<double>()))
            fail("expected > " + schema["exclusiveMinimum"].dump() + ", got " + shown(value));
        if (schema.contains("exclusiveMaximum") && !(x < schema["exclusiveMaximum"].get<double>()))
            fail("expected < " + schema["exclusiveMaximum"].dump() + ", got " + shown(value));
    }
    if (value.is_string()) {
        const std::string text = value.get<std::string>();
        if (schema.contains("minLength") && text.size() < schema["minLength"].get<size_t>())
            fail("expected at least " + schema["minLength"].dump() + " characters");
        if (schema.contains("pattern") &&
            !std::regex_search(text, std::regex(schema["pattern"].get<std::string>())))
            fail("expected a string matching " + schema["pattern"].dump() + ", got " + shown(value));
    }
    if (value.is_array()) {
        if (schema.contains("minItems") && value.size() < schema["minItems"].get<size_t>())
            fail("expected at least " + schema["minItems"].dump() + " items, got " +
                 std::to_string(value.size()));
        if (schema.contains("maxItems") && value.size() > schema["maxItems"].get<size_t>())
            fail("expected at most " + schema["maxItems"].dump() + " items, got " +
                 std::to_string(value.size()));
        if (schema.value("uniqueItems", false))
            for (size_t i = 0; i < value.size(); ++i)
                for (size_t j = i + 1; j < value.size(); ++j)
                    if (value[i] == value[j]) fail("item " + shown(value[j]) + " is listed twice");
        if (schema.contains("items"))
            for (size_t i = 0; i < value.size(); ++i)
                check(schema["items"], value[i], path + "[" + std::to_string(i) + "]", problems);
    }
    if (value.is_object()) {
        if (schema.contains("required"))
            for (const Json& key : schema["required"])
                if (!value.contains(key.get<std::string>())) fail("missing " + key.dump());
        const Json properties = schema.value("properties", Json::object());
        for (const auto& [key, item] : value.items()) {
            if (properties.contains(key))
                check(properties[key], item, child(path, key), problems);
            else if (schema.value("additionalProperties", Json(true)) == Json(false))
                problems.push_back(child(path, key) + ": unknown key");
            else if (schema.contains("additionalProperties"))
                check(schema["additionalProperties"], item, child(path, key), problems);
        }
    }
    for (const char* combination : {"oneOf", "anyOf"}) {
        if (!schema.contains(combination)) continue;
        int matching = 0;
        std::vector<std::string> closest;
        bool closestSameKind = false;
        for (const Json& branch : schema[combination]) {
            std::vector<std::string> own;
            check(branch, value, path, own);
            const bool kind = sameKind(branch, value);
            if (own.empty())
                ++matching;
            else if (closest.empty() || (kind && !closestSameKind) ||
                     (kind == closestSameKind && own.size() < closest.size())) {
                closest = own;
                closestSameKind = kind;
            }
        }
        const bool one = std::string(combination) == "oneOf";
        if (matching == 0) {
            fail(std::string("matches none of the ") + combination + " branches");
            problems.insert(problems.end(), closest.begin(), closest.end());  // the nearest branch's reasons
        } else if (one && matching > 1) {
            fail("matches " + std::to_string(matching) + " of the oneOf branches, expected exactly one");
        }
    }
}

}  // namespace btfracture::test
