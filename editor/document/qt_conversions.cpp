#include "editor/document/qt_conversions.h"

#include <QLocale>

#include <algorithm>
#include <cmath>

namespace regio::editor {

QStringList toQStringList(const std::vector<std::string>& ids)
{
    QStringList out;
    out.reserve(qsizetype(ids.size()));
    for (const std::string& id : ids)
        out << toQString(id);
    return out;
}

std::vector<std::string> toStdVector(const QStringList& ids)
{
    std::vector<std::string> out;
    out.reserve(size_t(ids.size()));
    for (const QString& id : ids)
        out.push_back(toStd(id));
    return out;
}

double linearToSrgb(double c)
{
    c = std::clamp(c, 0.0, 1.0);
    return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

double srgbToLinear(double c)
{
    c = std::clamp(c, 0.0, 1.0);
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

QColor linearToColor(const model::Rgb& rgb)
{
    return QColor::fromRgbF(float(linearToSrgb(rgb.r)), float(linearToSrgb(rgb.g)), float(linearToSrgb(rgb.b)));
}

model::Rgb colorToLinear(const QColor& colour)
{
    return {srgbToLinear(colour.redF()), srgbToLinear(colour.greenF()), srgbToLinear(colour.blueF())};
}

QColor emissionDisplayColor(const model::Rgb& emission)
{
    const double peak = std::max({emission.r, emission.g, emission.b});
    if (!(peak > 0.0))
        return QColor(Qt::black);
    return linearToColor(emission / peak);
}

QString formatNumber(double value, int precision) { return QLocale().toString(value, 'g', precision); }

QString formatVector(const model::Vec3& v, int precision)
{
    return QStringLiteral("(%1, %2, %3)")
        .arg(formatNumber(v.x, precision), formatNumber(v.y, precision), formatNumber(v.z, precision));
}

} // namespace regio::editor
