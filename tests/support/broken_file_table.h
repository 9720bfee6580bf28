#pragma once
// The tables of the bad-file catalogue, tests/data/bad: format.tsv says for
// every file the reader refuses
// which stage rejects it and where the diagnostic must point. Shared by the
// reader's tests and the CLI's, so both check the same promises.
#include <fstream>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

namespace regio::test {

struct BrokenFile {
    std::string name;  // file name in tests/data/bad
    std::string stage; // "format" (parseScene) or "validation" (validateScene)
    int line = 0;      // syntax errors: 1-based position, else 0
    int column = 0;
    std::string pointer; // JSON pointer; empty for the whole document
    std::string message; // a part of the expected message
};

// Test names print the file, not the bytes of the struct.
inline void PrintTo(const BrokenFile& file, std::ostream* out) { *out << file.name; }

inline std::string brokenDataDir() { return std::string(REGIO_TEST_DATA) + "/bad"; }

// Location column: "-", "/json/pointer", "LINE:COLUMN" or "LINE:COLUMN /pointer".
inline std::vector<BrokenFile> loadBrokenFileTable()
{
    std::vector<BrokenFile> table;
    std::ifstream in(brokenDataDir() + "/format.tsv");
    std::string row;
    while (std::getline(in, row)) {
        if (row.empty() || row[0] == '#')
            continue;
        std::vector<std::string> cells;
        std::stringstream split(row);
        for (std::string cell; std::getline(split, cell, '\t');)
            cells.push_back(cell);
        if (cells.size() != 4)
            continue;
        BrokenFile file{cells[0], cells[1], 0, 0, {}, cells[3]};
        std::string location = cells[2];
        if (!location.empty() && location[0] >= '0' && location[0] <= '9') {
            std::stringstream position(location);
            char colon = 0;
            position >> file.line >> colon >> file.column;
            std::string rest;
            position >> rest;
            file.pointer = rest;
        } else if (location != "-") {
            file.pointer = location;
        }
        table.push_back(std::move(file));
    }
    return table;
}

// Every file the catalogue lists: format.tsv (what the reader refuses) and
// validation.tsv (readable scenes that break a rule), first column.
inline std::vector<std::string> catalogueFileNames()
{
    std::vector<std::string> names;
    for (const char* table : {"/format.tsv", "/validation.tsv"}) {
        std::ifstream in(brokenDataDir() + table);
        for (std::string row; std::getline(in, row);)
            if (!row.empty() && row[0] != '#')
                names.push_back(row.substr(0, row.find('\t')));
    }
    return names;
}

} // namespace regio::test
