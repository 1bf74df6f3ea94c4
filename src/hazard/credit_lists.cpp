#include "hazard/credit_lists.hpp"

namespace hazard {

std::uint32_t CreditLists::new_node(const Credit& credit) {
  std::uint32_t id = free_;
  if (id == CreditList::kNone) {
    id = static_cast<std::uint32_t>(nodes_.size());
    nodes_.emplace_back();
  } else {
    free_ = nodes_[id].next;
  }
  nodes_[id] = Node{credit.pass, CreditList::kNone, credit.heading_deg};
  return id;
}

void CreditLists::push_back(CreditList& list, const Credit& credit) {
  const std::uint32_t id = new_node(credit);
  if (list.empty()) {
    list.first = id;
  } else {
    nodes_[list.last].next = id;
  }
  list.last = id;
  ++list.size;
}

Credit CreditLists::front(const CreditList& list) const {
  const Node& n = nodes_[list.first];
  return Credit{n.pass, n.heading_deg};
}

Credit CreditLists::pop_front(CreditList& list) {
  const std::uint32_t id = list.first;
  const Credit oldest = front(list);
  list.first = nodes_[id].next;
  if (--list.size == 0) list.last = CreditList::kNone;
  nodes_[id].next = free_;
  free_ = id;
  return oldest;
}

void CreditLists::insert_in_pass_order(CreditList& list, const Credit& credit) {
  if (list.empty() || credit.pass > nodes_[list.last].pass) return push_back(list, credit);
  const std::uint32_t id = new_node(credit);
  if (nodes_[list.first].pass >= credit.pass) {
    nodes_[id].next = list.first;
    list.first = id;
  } else {
    // The last node of a pass below the credit's; one exists (the first) and it is not the
    // list's last (whose pass is above).
    std::uint32_t before = list.first;
    while (nodes_[nodes_[before].next].pass < credit.pass) before = nodes_[before].next;
    nodes_[id].next = nodes_[before].next;
    nodes_[before].next = id;
  }
  ++list.size;
}

std::vector<Credit> CreditLists::to_vector(const CreditList& list) const {
  std::vector<Credit> out;
  out.reserve(list.size);
  for (std::uint32_t id = list.first; id != CreditList::kNone; id = nodes_[id].next) {
    out.push_back(Credit{nodes_[id].pass, nodes_[id].heading_deg});
  }
  return out;
}

std::size_t CreditLists::free_slots() const {
  std::size_t n = 0;
  for (std::uint32_t id = free_; id != CreditList::kNone; id = nodes_[id].next) ++n;
  return n;
}

}  // namespace hazard
