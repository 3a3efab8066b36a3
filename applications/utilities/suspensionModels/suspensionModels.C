/*---------------------------------------------------------------------------*\
Application
    suspensionModels

Description
    Prints the engine's registry of pair force models (forces/ForceModels.H)
    as Markdown: for every registered model its name, case dictionary,
    stress contribution and traits, and every case entry its read() asks
    for, with the allowed range and the meaning the model gives it. The
    table is the registry's own: a model added to PairModels appears here
    without a line written by hand (docs/models.md is its output).

Usage
    suspensionModels > docs/models.md
\*---------------------------------------------------------------------------*/

#include "forces/ForceModels.H"

#include <cmath>
#include <iostream>
#include <string>
#include <map>
#include <memory>
#include <sstream>

using namespace suspension;

namespace
{
    //- An entry a model asked for
    struct Entry
    {
        std::string dict;
        std::string name;
        std::string range;
        std::string meaning;
        bool required;
    };

    std::string show(const ModelInput::Range& r)
    {
        auto end = [](double x)
        {
            if (std::isinf(x)) return std::string("inf");
            std::ostringstream os;
            os << x;
            return os.str();
        };
        return std::string(r.minOpen ? "(" : "[") + end(r.min) + ", "
            + end(r.max) + (r.maxOpen ? ")" : "]");
    }

    //- A ModelInput that records what is asked and answers with a value
    //  inside the range (every optional entry counts as present)
    class Recorder
    :
        public ModelInput
    {
        std::string path_;
        std::vector<Entry>& entries_;
        mutable std::map<std::string, std::unique_ptr<Recorder>> others_;

        void record
        (
            const std::string& name,
            const std::string& range,
            const std::string& meaning,
            bool required
        ) const
        {
            for (const Entry& e : entries_)
            {
                if (e.dict == path_ && e.name == name) return;
            }
            entries_.push_back({path_, name, range, meaning, required});
        }

        const Recorder& at(const std::string& path) const
        {
            std::unique_ptr<Recorder>& r = others_[path];
            if (!r)
            {
                r = std::make_unique<Recorder>(path, entries_);
            }
            return *r;
        }

        static double inside(const Range& r)
        {
            return std::isinf(r.max) ? r.min + 1 : 0.5*(r.min + r.max);
        }

    public:

        Recorder(const std::string& path, std::vector<Entry>& entries)
        :
            path_(path),
            entries_(entries)
        {}

        double scalar
        (
            const std::string& name,
            const Range& range,
            const std::string& meaning
        ) const override
        {
            record(name, show(range), meaning, true);
            return inside(range);
        }

        double scalarOr
        (
            const std::string& name,
            double defaultValue,
            const Range& range,
            const std::string& meaning
        ) const override
        {
            // A default derived from other entries is stated in the meaning
            std::ostringstream d;
            d << show(range);
            if (meaning.find("default") == std::string::npos)
            {
                d << ", default " << defaultValue;
            }
            record(name, d.str(), meaning, false);
            return defaultValue;
        }

        std::string word
        (
            const std::string& name,
            const std::vector<std::string>& choices,
            bool optional,
            const std::string& meaning
        ) const override
        {
            std::string c;
            for (const std::string& w : choices)
            {
                c += (c.empty() ? "" : " or ") + w;
            }
            record(name, c, meaning, !optional);
            return choices.front();
        }

        bool found(const std::string&) const override
        {
            return true;
        }

        const ModelInput& parent() const override
        {
            const std::size_t slash = path_.rfind('/');
            return at(slash == std::string::npos ? "" : path_.substr(0, slash));
        }
    };

    const char* yes(bool b)
    {
        return b ? "yes" : "–";
    }

    //- Text for a cell of a Markdown table: '|' escaped, so that a
    //  model's text cannot split the row
    std::string cell(const std::string& text)
    {
        std::string out;
        for (const char c : text)
        {
            if (c == '|')
            {
                out += '\\';
            }
            out += c;
        }
        return out;
    }
}


int main()
{
    std::cout
        << "# Force models\n\n"
        << "Made by `suspensionModels > docs/models.md` from the registry "
           "`ParticleModels` and `PairModels` of "
           "`src/suspension/forces/ForceModels.H`; the "
           "entries are those each model's `read()` asks for "
           "(reduced units a0 = eta0 = gammaDot = 1). A model's dictionary in "
           "`constant/suspensionProperties` needs `active true;`; models "
           "sharing a dictionary are chosen by its `type` entry.\n\n"
        << "Pair models (`PairModels`):\n\n"
        << "| model (`type`) | dictionary | stress column | velocities | "
           "history | hydrodynamic | central |\n"
        << "|---|---|---|---|---|---|---|\n";

    std::vector<Entry> entries;
    auto readEntries = [&](auto tag)
    {
        using M = typename decltype(tag)::type;
        if constexpr (M::dictName[0] == '\0')
        {
            return;
        }
        else
        {
        std::vector<Entry> own;
        const Recorder input(M::dictName, own);
        M::read(input);
        for (Entry& e : own)
        {
            e.meaning = std::string(M::typeName) + ": " + e.meaning;
            bool known = false;
            for (const Entry& k : entries)
            {
                known = known || (k.dict == e.dict && k.name == e.name);
            }
            if (!known)
            {
                entries.push_back(e);
            }
        }
        }
    };
    forEachPairModelType([&](auto tag)
    {
        using M = typename decltype(tag)::type;
        std::cout
            << "| " << M::typeName << " | `" << M::dictName << "` | etaR_"
            << M::contribution << " | " << yes(M::usesVelocities) << " | "
            << yes(M::hasHistory) << " | " << yes(M::hydrodynamic) << " | "
            << yes(M::central) << " |\n";
        readEntries(tag);
    });

    std::cout
        << "\nPer-particle models (`ParticleModels`):\n\n"
        << "| model | dictionary | stress column | hydrodynamic |\n"
        << "|---|---|---|---|\n";
    forEachParticleModelType([&](auto tag)
    {
        using M = typename decltype(tag)::type;
        const std::string dict = M::dictName;
        std::cout
            << "| " << M::typeName << " | "
            << (dict.empty() ? std::string("(always on)") : "`" + dict + "`")
            << " | etaR_" << M::contribution << " | " << yes(M::hydrodynamic)
            << " |\n";
        readEntries(tag);
    });

    std::cout
        << "\n## Entries\n\n"
        << "| dictionary | entry | required | range | read by: meaning |\n"
        << "|---|---|---|---|---|\n";
    for (const Entry& e : entries)
    {
        std::cout
            << "| `" << e.dict << "` | " << e.name << " | "
            << (e.required ? "yes" : "no") << " | " << cell(e.range) << " | "
            << cell(e.meaning) << " |\n";
    }
    return 0;
}
