#pragma once
// Logical units of a run (code_aster "UNITE"): the .export's F lines map unit numbers to files.
// Inputs (D) are read in place; outputs (R) go to the named file, otherwise to fort.<unit> in the
// output folder.
#include <map>
#include <string>

namespace ma {

class Units {
public:
    void setInput(int unit, std::string path) { inputs_[unit] = std::move(path); }
    void setOutput(int unit, std::string path) { outputs_[unit] = std::move(path); }
    void setOutputDir(std::string dir) { outDir_ = std::move(dir); }
    const std::string& outputDir() const { return outDir_; }

    bool hasInput(int unit) const { return inputs_.count(unit) > 0; }
    // Path of the data file of `unit`; UserError when the .export does not provide it.
    std::string input(int unit) const;
    // Path where output unit `unit` must be written. UserError when that is a link, a FIFO or a
    // device already there (fort.N of the output folder: the F lines are checked before the run).
    std::string output(int unit) const;
    const std::map<int, std::string>& inputs() const { return inputs_; }
    const std::map<int, std::string>& outputs() const { return outputs_; }

private:
    std::map<int, std::string> inputs_, outputs_;
    std::string outDir_ = ".";
};

}  // namespace ma
