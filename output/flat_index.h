#pragma once
// Numbering of keys in flat arrays, for the shadings' lookups of points by
// integer coordinates: hundreds of thousands of them per mesh, where a
// node-based map spends more time allocating and chasing pointers than
// comparing keys.
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <utility>
#include <vector>

namespace regio::output {

// A hash of integer coordinates: FNV-1a over the whole values, then mixed
// (MurmurHash3's finaliser) so that the low bits, which pick the slot, and
// the high bits, which tell keys apart, depend on every bit of every
// coordinate.
inline std::uint64_t hashIntegers(std::initializer_list<std::int64_t> values)
{
    std::uint64_t h = 1469598103934665603ull;
    for (const std::int64_t v : values)
        h = (h ^ static_cast<std::uint64_t>(v)) * 1099511628211ull;
    h ^= h >> 33;
    h *= 0xff51afd7ed558ccdull;
    h ^= h >> 33;
    h *= 0xc4ceb9fe1a85ec53ull;
    h ^= h >> 33;
    return h;
}

// Numbers distinct keys 0, 1, 2, ... in the order they come; the caller
// keeps whatever belongs to a key in arrays by that number. The table holds
// only the numbers and a part of each hash (8 bytes a slot, linear probing,
// at most half full), the keys lie in one array: most probes touch one
// cache line. Keys need operator==; Hash(key) gives a uint64. Nothing is
// ever removed.
template <typename Key, typename Hash>
class FlatIndex {
public:
    static constexpr std::uint32_t kNone = ~std::uint32_t(0);

    explicit FlatIndex(size_t expected = 0) { reserve(expected); }

    size_t size() const { return m_keys.size(); }
    const Key& key(std::uint32_t index) const { return m_keys[index]; }

    // Room for `count` keys without growing.
    void reserve(size_t count)
    {
        m_keys.reserve(count);
        size_t capacity = 16;
        while (capacity < 2 * count)
            capacity *= 2;
        if (capacity > m_slots.size())
            rehash(capacity);
    }

    // The key's number, given it now if it had none (then the bool is true).
    std::pair<std::uint32_t, bool> insert(const Key& key)
    {
        if (2 * (m_keys.size() + 1) > m_slots.size())
            rehash(2 * m_slots.size());
        const std::uint64_t h = Hash{}(key);
        Slot& slot = m_slots[slotOf(key, h)];
        if (slot.index != kNone)
            return {slot.index, false};
        slot = {std::uint32_t(m_keys.size()), tagOf(h)};
        m_keys.push_back(key);
        return {slot.index, true};
    }

    // The key's number, or kNone.
    std::uint32_t find(const Key& key) const { return m_slots[slotOf(key, Hash{}(key))].index; }

private:
    struct Slot {
        std::uint32_t index = kNone;
        std::uint32_t tag = 0; // the hash's high half
    };

    static std::uint32_t tagOf(std::uint64_t h) { return std::uint32_t(h >> 32); }

    // The key's slot, or the empty slot where it would go.
    size_t slotOf(const Key& key, std::uint64_t h) const
    {
        const size_t mask = m_slots.size() - 1;
        const std::uint32_t tag = tagOf(h);
        for (size_t i = static_cast<size_t>(h) & mask;; i = (i + 1) & mask) {
            const Slot& slot = m_slots[i];
            if (slot.index == kNone || (slot.tag == tag && m_keys[slot.index] == key))
                return i;
        }
    }

    void rehash(size_t capacity)
    {
        m_slots.assign(capacity, Slot{});
        const size_t mask = capacity - 1;
        for (std::uint32_t k = 0; k < m_keys.size(); ++k) {
            const std::uint64_t h = Hash{}(m_keys[k]);
            size_t i = static_cast<size_t>(h) & mask;
            while (m_slots[i].index != kNone)
                i = (i + 1) & mask;
            m_slots[i] = {k, tagOf(h)};
        }
    }

    std::vector<Slot> m_slots = std::vector<Slot>(16);
    std::vector<Key> m_keys;
};

} // namespace regio::output
