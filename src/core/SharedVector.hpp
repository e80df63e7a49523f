#pragma once
// A vector whose storage several owners may share, copied the first time one of them changes it
// (copy on write). The point geometry of integration-point fields (fields/Fields.hpp) is the same
// for every result of a model: ~10^6 points of a 3D front's crack-tip elements, 60 bytes each.
// Reading goes through the const interface; every change goes through mut() or the few mutators
// below, which detach a shared storage first.
#include <cstddef>
#include <initializer_list>
#include <memory>
#include <vector>

namespace ma {

template <class T>
class SharedVector {
public:
    using value_type = T;
    using size_type = std::size_t;
    using const_iterator = typename std::vector<T>::const_iterator;

    SharedVector() = default;
    SharedVector(std::initializer_list<T> values) : data_(std::make_shared<std::vector<T>>(values)) {}
    SharedVector(std::vector<T> values) : data_(std::make_shared<std::vector<T>>(std::move(values))) {}
    SharedVector& operator=(std::vector<T> values) {
        data_ = std::make_shared<std::vector<T>>(std::move(values));
        return *this;
    }
    SharedVector& operator=(std::initializer_list<T> values) { return *this = std::vector<T>(values); }

    const std::vector<T>& get() const { return data_ ? *data_ : empty_(); }
    operator const std::vector<T>&() const { return get(); }
    size_type size() const { return get().size(); }
    bool empty() const { return get().empty(); }
    const T& operator[](size_type i) const { return get()[i]; }
    const T& front() const { return get().front(); }
    const T& back() const { return get().back(); }
    const T* data() const { return get().data(); }
    const_iterator begin() const { return get().begin(); }
    const_iterator end() const { return get().end(); }
    friend bool operator==(const SharedVector& a, const SharedVector& b) { return a.get() == b.get(); }

    // The storage to change, this owner's alone (copied first when shared).
    std::vector<T>& mut() {
        if (!data_) data_ = std::make_shared<std::vector<T>>();
        else if (data_.use_count() > 1) data_ = std::make_shared<std::vector<T>>(*data_);
        return *data_;
    }
    void push_back(const T& value) { mut().push_back(value); }
    void reserve(size_type n) { mut().reserve(n); }
    void resize(size_type n) { mut().resize(n); }
    // The storage to overwrite whole, this owner's alone and empty (a shared one is left to the
    // others, not copied): a reused scratch keeps its capacity.
    std::vector<T>& overwrite() {
        if (!data_ || data_.use_count() > 1) data_ = std::make_shared<std::vector<T>>();
        else data_->clear();
        return *data_;
    }
    void assign(size_type n, const T& value) { overwrite().assign(n, value); }
    template <class It>
    void assign(It first, It last) {
        overwrite().assign(first, last);
    }
    void clear() { data_.reset(); }
    template <class It>
    void insert(const_iterator at, It first, It last) {
        const auto offset = at - begin();
        auto& v = mut();
        v.insert(v.begin() + offset, first, last);
    }
    void insert(const_iterator at, size_type n, const T& value) {
        const auto offset = at - begin();
        auto& v = mut();
        v.insert(v.begin() + offset, n, value);
    }

    // Sharing: the storage as it is now, for a cache that watches it without keeping it.
    std::weak_ptr<const std::vector<T>> watch() const { return data_; }
    // Takes `other`'s storage as it is (the caller checks the values); false when it is gone.
    bool adopt(const std::weak_ptr<const std::vector<T>>& other) {
        const auto held = other.lock();
        if (held) data_ = std::const_pointer_cast<std::vector<T>>(held);
        return held != nullptr;
    }

private:
    static const std::vector<T>& empty_() {
        static const std::vector<T> none;
        return none;
    }
    std::shared_ptr<std::vector<T>> data_;  // null: empty
};

}  // namespace ma
