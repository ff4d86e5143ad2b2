// SPDX-License-Identifier: Zlib
#pragma once
// A validator for the subset of JSON Schema (draft 2020-12) that demos/scenes/scene.schema.json
// uses, so that a test can check every shipped scene against the schema without a network or a
// tool outside Debian. Keywords: $ref (to "#/$defs/<name>"), type, properties, required,
// additionalProperties, items, minItems, maxItems, uniqueItems, enum, const, minimum, maximum,
// exclusiveMinimum, exclusiveMaximum, minLength, pattern, oneOf, anyOf; annotations ($schema,
// $id, $defs, title, description) are skipped. Any other keyword is an error in the schema, so
// the schema cannot use what this validator would silently ignore.
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace btfracture::test {

class JsonSchema {
public:
    // Throws std::runtime_error when the schema uses a keyword outside the subset.
    explicit JsonSchema(nlohmann::json schema);

    // Problems of `instance`, each "<path>: <what>" (path like bodies[1].shape.type); empty
    // when it is valid.
    std::vector<std::string> validate(const nlohmann::json& instance) const;

    const nlohmann::json& root() const { return root_; }
    // The schema node "#/$defs/<name>".
    const nlohmann::json& definition(const std::string& name) const;

private:
    void check(const nlohmann::json& schema, const nlohmann::json& value, const std::string& path,
               std::vector<std::string>& problems) const;
    const nlohmann::json& resolve(const nlohmann::json& schema) const;
    bool sameKind(const nlohmann::json& schema, const nlohmann::json& value) const;
    void requireKnownKeywords(const nlohmann::json& schema) const;

    nlohmann::json root_;
};

}  // namespace btfracture::test
