#include "rheologySeries.H"
#include "OSspecific.H"
#include "error.H"

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Subdirectories (or files matching the pattern) in the order of the time
//  their name holds; names that are no time are left out
template<class Filter>
std::vector<std::pair<double, Foam::fileName>> byTime
(
    const Foam::fileNameList& entries,
    Filter timeOf
)
{
    std::vector<std::pair<double, Foam::fileName>> out;
    for (const Foam::fileName& e : entries)
    {
        double t;
        if (timeOf(e, t))
        {
            out.emplace_back(t, e);
        }
    }
    std::stable_sort
    (
        out.begin(), out.end(),
        [](const auto& a, const auto& b) { return a.first < b.first; }
    );
    return out;
}

bool readTime(const std::string& s, double& t)
{
    std::istringstream is(s);
    return (is >> t) && is.eof();
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rheologySeries::rheologySeries(const fileName& dir, const scalar tEnd)
{
    // Rows by time: a later file replaces the rows from its first time on
    std::map<double, std::vector<double>> rows;

    const auto starts = byTime
    (
        readDir(dir, fileName::DIRECTORY),
        [](const fileName& d, double& t) { return readTime(d, t); }
    );
    for (const auto& start : starts)
    {
        // rheology.dat first, then the reruns rheology_<time>.dat in order
        std::vector<fileName> files;
        if (isFile(dir/start.second/"rheology.dat"))
        {
            files.push_back(dir/start.second/"rheology.dat");
        }
        const auto reruns = byTime
        (
            readDir(dir/start.second, fileName::FILE),
            [](const fileName& f, double& t)
            {
                const std::string s(f);
                const std::string pre("rheology_"), post(".dat");
                return s.size() > pre.size() + post.size()
                    && s.compare(0, pre.size(), pre) == 0
                    && s.compare(s.size() - post.size(), post.size(), post) == 0
                    && readTime(s.substr(pre.size(), s.size() - pre.size() - post.size()), t);
            }
        );
        for (const auto& r : reruns)
        {
            files.push_back(dir/start.second/r.second);
        }

        for (const fileName& f : files)
        {
            std::ifstream is(f);
            std::string line;
            bool first = true;
            while (std::getline(is, line))
            {
                if (line.empty())
                {
                    continue;
                }
                std::istringstream ls(line);
                if (line[0] == '#')
                {
                    std::string hash, word0;
                    ls >> hash >> word0;
                    if (hash == "#" && word0 == "Time")
                    {
                        names_.clear();
                        names_.append(word(word0));
                        std::string w;
                        while (ls >> w)
                        {
                            names_.append(word(w));
                        }
                    }
                    continue;
                }
                std::vector<double> row;
                double v;
                while (ls >> v)
                {
                    row.push_back(v);
                }
                if (row.size() != size_t(names_.size()))
                {
                    // A row cut short by a run that was killed: the end of
                    // that file
                    break;
                }
                if (first)
                {
                    rows.erase(rows.lower_bound(row[0]), rows.end());
                    first = false;
                }
                if (row[0] <= tEnd*(1 + 1e-12) + 1e-300)
                {
                    rows[row[0]] = std::move(row);
                }
            }
        }
    }

    columns_.assign(names_.size(), std::vector<double>());
    for (const auto& r : rows)
    {
        if (r.second.size() != size_t(names_.size()))
        {
            continue;           // a row of an older layout
        }
        for (label c = 0; c < names_.size(); ++c)
        {
            columns_[c].push_back(r.second[c]);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

const std::vector<double>& Foam::rheologySeries::column(const word& name) const
{
    const label c = names_.find(name);
    if (c < 0)
    {
        FatalErrorInFunction
            << "No column " << name << " in the rheology series; columns: "
            << names_ << exit(FatalError);
    }
    return columns_[c];
}


// ************************************************************************* //
