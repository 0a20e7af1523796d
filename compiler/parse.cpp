#include "compiler/parse.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>
#include <vector>

#include "compiler/syntax_errors.hpp"
#include "compiler/units.hpp"
#include "grammar/EscLexer.h"
#include "grammar/EscParser.h"

namespace esc::compiler {

namespace {

using P = grammar::EscParser;
constexpr std::size_t kNoIndex = static_cast<std::size_t>(-1);

// An identifier right after a number is its unit when attached (`60cm`, `60cn`) or a unit
// name (`0.5 m/s^2`); the denominator of a compound unit must be a unit name.
void retype_units(antlr4::CommonTokenStream& tokens) {
  auto toks = tokens.getTokens();
  for (std::size_t i = 1; i < toks.size(); ++i) {
    antlr4::Token* t = toks[i];
    if (t->getType() != P::ID) continue;
    const antlr4::Token* prev = toks[i - 1];
    bool unit = false;
    if (prev->getType() == P::NUMBER)
      unit = prev->getStopIndex() + 1 == t->getStartIndex() || is_unit_word(t->getText());
    else if (prev->getType() == P::SLASH && i >= 2 && toks[i - 2]->getType() == P::UNIT)
      unit = is_unit_word(t->getText());
    if (unit)
      if (auto* w = dynamic_cast<antlr4::WritableToken*>(t)) w->setType(P::UNIT);
  }
}

bool ends_operand(std::size_t type) {
  switch (type) {
    case P::NUMBER: case P::UNIT: case P::RPAREN: case P::RBRACK: case P::TRUE: case P::FALSE:
    case P::STRING: return true;
    default: return type == P::ID || (type >= P::X && type <= P::OFF);
  }
}

// The parser recurses once per bracket and per prefix operator; refuse input deeper than
// kMaxNesting before parsing, so that no input can overflow the stack.
const antlr4::Token* too_deep(antlr4::CommonTokenStream& tokens) {
  std::vector<int> pressure{0};
  int total = 0;
  std::size_t prev = P::LBRACE;
  for (antlr4::Token* t : tokens.getTokens()) {
    const std::size_t ty = t->getType();
    switch (ty) {
      case P::LPAREN: case P::LBRACK: case P::LBRACE:
        pressure.push_back(0);
        ++total;
        break;
      case P::RPAREN: case P::RBRACK: case P::RBRACE:
        if (pressure.size() > 1) {
          total -= pressure.back() + 1;
          pressure.pop_back();
        }
        break;
      case P::MINUS: case P::PLUS:
        if (!ends_operand(prev)) {
          ++pressure.back();
          ++total;
        }
        break;
      case P::NOT: case P::IF: case P::CARET:
        ++pressure.back();
        ++total;
        break;
      default: break;
    }
    if (total > kMaxNesting) return t;
    prev = ty;
  }
  return nullptr;
}

class Builder {
 public:
  Builder(std::filesystem::path file, const CleanText& text, antlr4::CharStream& chars, Sink& sink,
          const std::vector<std::size_t>& errors)
      : file_(std::move(file)), text_(text.display), chars_(chars), sink_(sink), errors_(errors) {}

  void build(P::ScriptContext* script, ast::Module& m) {
    if (script == nullptr) return;
    int order = 0;
    for (P::DeclContext* d : script->decl()) {
      if (d == nullptr) continue;
      ++order;
      if (auto* im = d->importDecl()) import_decl(im, m);
      else if (auto* ar = d->arenaDecl()) m.arenas.push_back(arena(ar, order));
      else if (auto* ro = d->robotDecl()) m.robots.push_back(robot(ro, order));
      else if (auto* be = d->behaviorDecl()) m.behaviors.push_back(behavior(be, order));
      else if (auto* fi = d->fitnessDecl()) m.fitnesses.push_back(fitness(fi, order));
      else if (auto* co = d->controllerDecl()) m.controllers.push_back(controller(co, order));
      else if (auto* ex = d->experimentDecl()) m.experiments.push_back(experiment(ex, order));
      else if (auto* li = d->libraryDecl()) library(li, m, order);
      else if (auto* pr = d->primitivesDecl()) m.primitives.push_back(primitives(pr, order));
      else if (auto* st = d->studyDecl()) m.studies.push_back(study(st, order));
    }
  }

 private:
  SourceRange at(const antlr4::Token* t) const { return token_range(file_, t); }

  SourceRange span(antlr4::ParserRuleContext* c) const {
    SourceRange r{file_, 0, 0, 1};
    if (c == nullptr || c->getStart() == nullptr) return r;
    r = at(c->getStart());
    const antlr4::Token* stop = c->getStop();
    if (stop == nullptr || stop->getTokenIndex() == kNoIndex ||
        stop->getTokenIndex() < c->getStart()->getTokenIndex() || stop->getType() == antlr4::Token::EOF)
      return r;
    const SourceRange s = at(stop);
    if (s.line == r.line) {
      r.length = std::max(1, s.column + s.length - r.column);
    } else {
      const int line_len = utf8_length(line_of(text_, r.line));
      r.length = std::max(1, line_len - r.column + 1);
    }
    return r;
  }

  std::string source(antlr4::ParserRuleContext* c) const {
    if (c == nullptr || c->getStart() == nullptr || c->getStop() == nullptr) return {};
    const std::size_t a = c->getStart()->getStartIndex(), b = c->getStop()->getStopIndex();
    if (a == kNoIndex || b == kNoIndex || b < a) return {};
    try {
      return chars_.getText(antlr4::misc::Interval(a, b));
    } catch (...) {
      return {};
    }
  }

  bool poisoned(antlr4::ParserRuleContext* c) const {
    if (c == nullptr || c->getStart() == nullptr) return true;
    const std::size_t a = c->getStart()->getTokenIndex();
    std::size_t b = c->getStop() != nullptr ? c->getStop()->getTokenIndex() : a;
    if (b == kNoIndex || b < a) b = a;
    return std::any_of(errors_.begin(), errors_.end(),
                       [&](std::size_t e) { return e != kNoIndex && e >= a && e <= b + 1; });
  }

  static bool missing(antlr4::tree::TerminalNode* n) {
    return n == nullptr || n->getSymbol() == nullptr || n->getSymbol()->getTokenIndex() == kNoIndex ||
           dynamic_cast<antlr4::tree::ErrorNode*>(n) != nullptr;
  }

  ast::Name name(P::IdentContext* c) const {
    ast::Name n;
    if (c == nullptr) return n;
    n.where = span(c);
    if (c->children.empty()) return n;
    auto* t = dynamic_cast<antlr4::tree::TerminalNode*>(c->children[0]);
    if (missing(t)) return n;
    n.text = t->getText();
    n.where = at(t->getSymbol());
    return n;
  }

  ast::Quantity number(antlr4::tree::TerminalNode* n, const antlr4::Token* sign = nullptr) {
    ast::Quantity q;
    if (missing(n)) {
      q.finite = false;
      return q;
    }
    const std::string text = n->getText();
    q.text = (sign != nullptr ? sign->getText() : std::string()) + text;
    q.where = at(sign != nullptr ? sign : n->getSymbol());
    if (sign != nullptr) {
      const SourceRange e = at(n->getSymbol());
      if (e.line == q.where.line) q.where.length = e.column + e.length - q.where.column;
    }
    double v = 0.0;
    const auto res = std::from_chars(text.data(), text.data() + text.size(), v);
    if (res.ec != std::errc() || !std::isfinite(v)) {
      if (res.ec == std::errc::result_out_of_range && text.find_first_of("eE") != std::string::npos &&
          (text.find("e-") != std::string::npos || text.find("E-") != std::string::npos)) {
        v = 0.0;   // underflow: as good as zero
      } else {
        sink_.error(at(n->getSymbol()), "number `" + text + "` is too large");
        q.finite = false;
        v = 0.0;
      }
    }
    q.value = (sign != nullptr && sign->getType() == P::MINUS) ? -v : v;
    return q;
  }

  void add_unit(ast::Quantity& q, P::UnitContext* u) const {
    if (u == nullptr) return;
    std::string s;
    for (antlr4::tree::ParseTree* ch : u->children) {
      auto* t = dynamic_cast<antlr4::tree::TerminalNode*>(ch);
      if (t == nullptr || missing(t)) continue;
      s += t->getText();
    }
    q.unit = s;
    q.unit_where = span(u);
    if (q.unit_where.line == q.where.line)
      q.where.length = std::max(q.where.length, q.unit_where.column + q.unit_where.length - q.where.column);
  }

  ast::Quantity quantity(P::QuantityContext* c) {
    if (c == nullptr) {
      ast::Quantity q;
      q.finite = false;
      return q;
    }
    ast::Quantity q = number(c->NUMBER(), c->sign);
    add_unit(q, c->unit());
    return q;
  }

  ast::Value value(P::ValueContext* c) {
    ast::Value v;
    if (c == nullptr) return v;
    v.where = span(c);
    v.text = source(c);
    if (c->quantity() != nullptr) {
      v.kind = ast::Value::Kind::Quantity;
      v.q = quantity(c->quantity());
    } else {
      v.kind = ast::Value::Kind::Bool;
      v.flag = c->ON() != nullptr || c->TRUE() != nullptr;
    }
    return v;
  }

  ast::Value list(P::QuantityListContext* c) {
    ast::Value v;
    v.kind = ast::Value::Kind::List;
    v.where = span(c);
    v.text = source(c);
    for (P::QuantityContext* q : c->quantity()) v.list.push_back(quantity(q));
    if (!c->quantityTuple().empty()) v.kind = ast::Value::Kind::Tuples;
    for (P::QuantityTupleContext* t : c->quantityTuple()) {
      ast::QuantityTuple& tuple = v.tuples.emplace_back();
      tuple.where = span(t);
      for (P::QuantityContext* q : t->quantity()) tuple.items.push_back(quantity(q));
    }
    return v;
  }

  std::vector<ast::Setting> settings(P::SettingsBlockContext* c) {
    std::vector<ast::Setting> out;
    if (c == nullptr) return out;
    for (P::SettingContext* s : c->setting()) {
      if (s == nullptr) continue;
      if (s->word != nullptr) {
        ast::Value v;
        v.kind = ast::Value::Kind::Word;
        v.text = name(s->word).text;
        v.where = span(s->word);
        out.push_back({name(s->key), std::move(v)});
        continue;
      }
      out.push_back({name(s->key), s->list != nullptr ? list(s->list) : value(s->value())});
    }
    return out;
  }

  void head(ast::DeclHead& h, antlr4::ParserRuleContext* c, P::IdentContext* n, int order) const {
    h.name = name(n);
    h.keyword = at(c->getStart());
    h.poisoned = poisoned(c) || h.name.text.empty();
    h.order = order;
    if (h.name.text.empty()) h.name.where = h.keyword;
  }

  void import_decl(P::ImportDeclContext* c, ast::Module& m) const {
    if (poisoned(c) || missing(c->STRING())) return;
    std::string raw = c->STRING()->getText();
    std::string path;
    for (std::size_t i = 1; i + 1 < raw.size(); ++i) {
      if (raw[i] == '\\' && i + 2 < raw.size()) ++i;
      path += raw[i];
    }
    m.imports.push_back({path, at(c->STRING()->getSymbol())});
  }

  ast::ArenaDecl arena(P::ArenaDeclContext* c, int order) {
    ast::ArenaDecl a;
    head(a, c, c->name, order);
    for (P::ArenaItemContext* it : c->arenaItem()) {
      if (auto* s = dynamic_cast<P::ArenaSizeContext*>(it)) {
        a.sizes.push_back({quantity(s->w), quantity(s->h), span(s)});
      } else if (auto* cy = dynamic_cast<P::ArenaCylinderContext*>(it)) {
        ast::Cylinder k;
        if (auto* p = cy->point()) {
          k.x = quantity(p->x);
          k.y = quantity(p->y);
        }
        k.radius = quantity(cy->r);
        k.where = span(cy);
        a.cylinders.push_back(std::move(k));
      } else if (auto* b = dynamic_cast<P::ArenaBlockContext*>(it)) {
        ast::Block k;
        if (auto* p = b->point()) {
          k.x = quantity(p->x);
          k.y = quantity(p->y);
        }
        k.w = quantity(b->w);
        k.h = quantity(b->h);
        if (b->a != nullptr) k.angle = quantity(b->a);
        k.where = span(b);
        a.blocks.push_back(std::move(k));
      } else if (auto* w = dynamic_cast<P::ArenaWallContext*>(it)) {
        ast::Wall k;
        if (w->p1 != nullptr) {
          k.x1 = quantity(w->p1->x);
          k.y1 = quantity(w->p1->y);
        }
        if (w->p2 != nullptr) {
          k.x2 = quantity(w->p2->x);
          k.y2 = quantity(w->p2->y);
        }
        if (w->t != nullptr) k.thickness = quantity(w->t);
        k.where = span(w);
        a.walls.push_back(std::move(k));
      } else if (auto* g = dynamic_cast<P::ArenaGoalContext*>(it)) {
        ast::Goal k;
        if (auto* p = g->point()) {
          k.x = quantity(p->x);
          k.y = quantity(p->y);
        }
        k.where = span(g);
        a.goals.push_back(std::move(k));
      } else if (auto* r = dynamic_cast<P::ArenaStartRandomContext*>(it)) {
        ast::Start st;
        st.random = true;
        st.where = span(r);
        a.starts.push_back(std::move(st));
      } else if (auto* l = dynamic_cast<P::ArenaLightContext*>(it)) {
        ast::Light k;
        k.name = name(l->name);
        if (auto* p = l->point()) {
          k.x = quantity(p->x);
          k.y = quantity(p->y);
        }
        if (l->zone != nullptr) k.above = name(l->zone);
        if (l->h != nullptr) k.height = quantity(l->h);
        if (l->i != nullptr) k.intensity = quantity(l->i);
        k.where = span(l);
        a.lights.push_back(std::move(k));
      } else if (auto* z = dynamic_cast<P::ArenaZoneContext*>(it)) {
        ast::Zone k;
        k.name = name(z->name);
        k.circle = z->CIRCLE() != nullptr;
        if (z->r != nullptr) k.radius = quantity(z->r);
        if (z->w != nullptr) k.w = quantity(z->w);
        if (z->h != nullptr) k.h = quantity(z->h);
        k.random = z->RANDOM() != nullptr;
        if (auto* p = z->point()) {
          k.x = quantity(p->x);
          k.y = quantity(p->y);
        }
        for (P::ZoneFlagContext* f : z->zoneFlag()) {
          if (f == nullptr || f->getStart() == nullptr) continue;
          k.flags.push_back({f->getStart()->getText(), at(f->getStart())});
        }
        k.where = span(z);
        a.zones.push_back(std::move(k));
      } else if (auto* sc = dynamic_cast<P::ArenaSweepCellContext*>(it)) {
        a.sweep_cells.push_back({quantity(sc->q), span(sc)});
      } else if (auto* rr = dynamic_cast<P::ArenaReachRadiusContext*>(it)) {
        a.reach_radii.push_back({quantity(rr->q), span(rr)});
      } else if (auto* f = dynamic_cast<P::ArenaStartAtContext*>(it)) {
        ast::Start st;
        st.random = false;
        if (auto* p = f->point()) {
          st.x = quantity(p->x);
          st.y = quantity(p->y);
        }
        if (f->a != nullptr) st.heading = quantity(f->a);
        st.where = span(f);
        a.starts.push_back(std::move(st));
      }
    }
    return a;
  }

  ast::RobotDecl robot(P::RobotDeclContext* c, int order) {
    ast::RobotDecl r;
    head(r, c, c->name, order);
    if (c->base != nullptr) r.base = name(c->base);
    r.settings = settings(c->settingsBlock());
    return r;
  }

  ast::BehaviorDecl behavior(P::BehaviorDeclContext* c, int order) {
    ast::BehaviorDecl b;
    head(b, c, c->name, order);
    if (c->EVOLVED() != nullptr) {
      b.evolved = true;
      if (c->exp != nullptr) b.from_experiment = name(c->exp);
      if (c->ctl != nullptr) b.from_controller = name(c->ctl);
      return b;
    }
    const auto ids = c->ident();
    for (std::size_t i = 1; i < ids.size(); ++i) b.params.push_back(name(ids[i]));
    if (P::CallContext* call = c->body) {
      b.body_fn = name(call->fn);
      b.body_where = span(call);
      for (P::ExprContext* e : call->expr()) {
        b.body_text.push_back(source(e));
        b.body_args.push_back(expr(e));
      }
    }
    return b;
  }

  // The members become behaviors named `L.member`, declared right after the library.
  void library(P::LibraryDeclContext* c, ast::Module& m, int& order) {
    ast::LibraryDecl l;
    head(l, c, c->name, order);
    if (c->mark != nullptr) l.mark = name(c->mark);
    for (P::BehaviorDeclContext* b : c->behaviorDecl()) {
      if (b == nullptr) continue;
      ast::BehaviorDecl d = behavior(b, ++order);
      d.member = d.name.text;
      d.library = l.name.text;
      d.useless = l.mark && l.mark->text == "useless";
      if (!d.name.text.empty()) d.name.text = l.name.text + "." + d.member;
      l.members.push_back(d.name.text);
      m.behaviors.push_back(std::move(d));
    }
    m.libraries.push_back(std::move(l));
  }

  ast::FitnessDecl fitness(P::FitnessDeclContext* c, int order) {
    ast::FitnessDecl f;
    head(f, c, c->name, order);
    for (P::FitnessItemContext* it : c->fitnessItem()) {
      if (auto* s = dynamic_cast<P::FitnessStepContext*>(it))
        f.steps.push_back({expr(s->expr()), source(s->expr()), at(s->getStart())});
      else if (auto* s2 = dynamic_cast<P::FitnessStopContext*>(it))
        f.stops.push_back({expr(s2->expr()), source(s2->expr()), at(s2->getStart())});
      else if (auto* s3 = dynamic_cast<P::FitnessEpochContext*>(it))
        f.epoch_ends.push_back({expr(s3->expr()), source(s3->expr()), at(s3->getStart())});
      else if (auto* s4 = dynamic_cast<P::FitnessEvaluationContext*>(it))
        f.evaluation_ends.push_back({expr(s4->expr()), source(s4->expr()), at(s4->getStart())});
      else if (auto* s5 = dynamic_cast<P::FitnessOverContext*>(it))
        f.overs.push_back({name(s5->what), name(s5->reduce), span(s5)});
    }
    return f;
  }

  void network(P::NetworkContext* n, ast::ControllerDecl& d) {
    if (n == nullptr) return;
    for (P::InputContext* in : n->input()) {
      if (in == nullptr) continue;
      ast::Input i;
      i.name = name(in->ident());
      i.where = span(in);
      if (in->lo != nullptr) {
        auto nums = in->NUMBER();
        if (!nums.empty()) i.lo = number(nums[0]);
        if (nums.size() > 1) i.hi = number(nums[1]);
      }
      d.inputs.push_back(std::move(i));
    }
    for (P::LayerContext* l : n->layer()) {
      if (l == nullptr) continue;
      ast::Layer layer;
      layer.word = name(l->ident());
      layer.where = span(l);
      if (l->NUMBER() != nullptr) layer.size = number(l->NUMBER());
      d.layers.push_back(std::move(layer));
    }
  }

  ast::ControllerDecl controller(P::ControllerDeclContext* c, int order) {
    ast::ControllerDecl d;
    head(d, c, c->name, order);
    if (auto* m = dynamic_cast<P::MlpControllerContext*>(c->controllerExpr())) {
      d.symbolic = false;
      d.elman = m->net != nullptr && m->net->getType() == P::ELMAN;
      d.neat = m->net != nullptr && m->net->getType() == P::NEAT;
      d.kind_where = at(m->getStart());
      network(m->network(), d);
    } else if (auto* s = dynamic_cast<P::SymbolicControllerContext*>(c->controllerExpr())) {
      d.symbolic = true;
      d.elman = s->net != nullptr && s->net->getType() == P::ELMAN;
      d.neat = s->net != nullptr && s->net->getType() == P::NEAT;
      d.kind_where = at(s->getStart());
      network(s->network(), d);
      for (P::IdentContext* a : s->ident()) d.actions.push_back(name(a));
    } else if (auto* v = dynamic_cast<P::SupervisorControllerContext*>(c->controllerExpr())) {
      d.supervisor = true;
      d.elman = v->net != nullptr && v->net->getType() == P::ELMAN;
      d.neat = v->net != nullptr && v->net->getType() == P::NEAT;
      d.kind_where = at(v->getStart());
      network(v->network(), d);
      supervised(v->supervised(), d);
    } else if (auto* t = dynamic_cast<P::TreeControllerContext*>(c->controllerExpr())) {
      d.tree = true;
      d.kind_where = at(t->getStart());
      if (t->prims != nullptr) d.primitives = name(t->prims);
      if (P::TreeResultContext* r = t->treeResult()) {
        d.symbolic = r->ACTIONS() != nullptr;
        d.supervisor = r->BEHAVIORS() != nullptr;
        if (d.symbolic)
          for (P::IdentContext* a : r->ident()) d.actions.push_back(name(a));
        else if (d.supervisor)
          supervised(r->supervised(), d);
        else if (!r->ident().empty())
          d.tree_result = name(r->ident()[0]);
      }
    } else if (auto* b = dynamic_cast<P::PerBodyControllerContext*>(c->controllerExpr())) {
      d.kind_where = at(b->getStart());
      for (P::BodyNetworkContext* n : b->bodyNetwork())
        if (n != nullptr && n->body != nullptr && n->ctl != nullptr) d.per_body.push_back({name(n->body), name(n->ctl)});
      if (d.per_body.empty()) d.poisoned = true;
    } else {
      d.poisoned = true;
    }
    return d;
  }

  void supervised(const std::vector<P::SupervisedContext*>& list, ast::ControllerDecl& d) {
    for (P::SupervisedContext* b : list) {
      if (b == nullptr) continue;
      ast::SupervisedRef r;
      r.name = name(b->ident(0));
      if (b->member != nullptr) {
        const ast::Name member = name(b->member);
        r.name.text += "." + member.text;
        r.name.where = span(b);
      }
      for (P::QuantityContext* q : b->quantity()) r.args.push_back(quantity(q));
      r.where = span(b);
      d.behaviors.push_back(std::move(r));
    }
  }

  ast::PrimitivesDecl primitives(P::PrimitivesDeclContext* c, int order) {
    ast::PrimitivesDecl p;
    head(p, c, c->name, order);
    for (P::PrimItemContext* it : c->primItem()) {
      if (auto* f = dynamic_cast<P::PrimFunctionsContext*>(it)) {
        for (P::PrimFunctionContext* fn : f->primFunction())
          if (fn != nullptr && fn->getStart() != nullptr)
            p.functions.push_back({fn->getStart()->getText(), at(fn->getStart())});
        continue;
      }
      auto* list = dynamic_cast<P::PrimTerminalsContext*>(it);
      if (list == nullptr) continue;
      for (P::PrimTerminalContext* t : list->primTerminal()) {
        ast::PrimTerminal k;
        k.where = span(t);
        if (auto* e = dynamic_cast<P::PrimErcContext*>(t)) {
          k.kind = ast::PrimTerminal::Kind::Erc;
          k.name = name(e->ident());
          k.lo = quantity(e->lo);
          k.hi = quantity(e->hi);
        } else if (auto* o = dynamic_cast<P::PrimObservableContext*>(t)) {
          k.kind = ast::PrimTerminal::Kind::Observable;
          k.name = name(o->ident());
          const auto nums = o->NUMBER();
          if (!nums.empty()) k.lo = number(nums[0]);
          if (nums.size() > 1) k.hi = number(nums[1]);
        } else if (auto* q = dynamic_cast<P::PrimConstantContext*>(t)) {
          k.kind = ast::PrimTerminal::Kind::Constant;
          k.value = quantity(q->quantity());
        } else if (auto* b = dynamic_cast<P::PrimBoolContext*>(t)) {
          k.kind = ast::PrimTerminal::Kind::Bool;
          k.flag = b->TRUE() != nullptr;
        } else {
          continue;
        }
        p.terminals.push_back(std::move(k));
      }
    }
    return p;
  }

  std::optional<ast::DeclaredRange> range(P::ObjRangeContext* c) {
    if (c == nullptr || c->lo == nullptr || c->hi == nullptr) return std::nullopt;
    return ast::DeclaredRange{quantity(c->lo), quantity(c->hi), span(c)};
  }

  ast::ExperimentDecl experiment(P::ExperimentDeclContext* c, int order) {
    ast::ExperimentDecl x;
    head(x, c, c->name, order);
    using K = ast::ExpItem::Kind;
    for (P::ExpItemContext* it : c->expItem()) {
      if (it == nullptr) continue;
      ast::ExpItem item;
      item.where = at(it->getStart());
      if (auto* a = dynamic_cast<P::ExpArenaContext*>(it)) {
        item.kind = K::Arena;
        item.refs.push_back(name(a->ident()));
      } else if (auto* r = dynamic_cast<P::ExpRobotContext*>(it)) {
        item.kind = K::Robot;
        for (P::GroupMemberContext* m : r->groupMember()) {
          ast::GroupMember member{name(m->ident()), settings(m->settingsBlock()), std::nullopt};
          if (m->NUMBER() != nullptr) member.count = number(m->NUMBER());
          if (item.refs.empty()) {   // the first body: the robot item as it always was
            item.refs.push_back(member.ref);
            item.settings = std::move(member.settings);
            if (member.count) item.numbers.push_back(*member.count);
          } else {
            item.members.push_back(std::move(member));
          }
        }
      } else if (auto* fm = dynamic_cast<P::ExpFormationContext*>(it)) {
        item.kind = K::Formation;
        item.refs.push_back(name(fm->kind));
        if (fm->spacing != nullptr) item.numbers.push_back(quantity(fm->spacing));
        if (fm->list != nullptr) item.list = list(fm->list);
      } else if (auto* ro = dynamic_cast<P::ExpRolesContext*>(it)) {
        item.kind = K::Roles;
        item.numbers.push_back(number(ro->NUMBER()));
      } else if (auto* e = dynamic_cast<P::ExpEpochsContext*>(it)) {
        item.kind = K::Epochs;
        for (auto* n : e->NUMBER()) item.numbers.push_back(number(n));
      } else if (auto* s = dynamic_cast<P::ExpStepsContext*>(it)) {
        item.kind = K::Steps;
        item.numbers.push_back(number(s->NUMBER()));
      } else if (auto* f = dynamic_cast<P::ExpFitnessContext*>(it)) {
        item.kind = K::Fitness;
        item.refs.push_back(name(f->ident()));
        item.range = range(f->objRange());
      } else if (auto* ob = dynamic_cast<P::ExpObjectiveContext*>(it)) {
        item.kind = K::Objective;
        item.refs.push_back(name(ob->ident()));
        item.minimize = ob->dir != nullptr && ob->dir->getType() == P::MINIMIZE;
        item.range = range(ob->objRange());
      } else if (auto* de = dynamic_cast<P::ExpDescriptorContext*>(it)) {
        item.kind = K::Descriptor;
        item.refs.push_back(name(de->name));
        item.expr = expr(de->expr());
        item.text = source(de->expr());
        item.at_evaluation = de->EVALUATION() != nullptr;
        item.range = range(de->objRange());
        if (de->reduce != nullptr) item.reduce = name(de->reduce);
        if (de->over != nullptr) item.overs.push_back({name(de->what), name(de->over), span(de)});
      } else if (auto* su = dynamic_cast<P::ExpSuccessContext*>(it)) {
        item.kind = K::Success;
        item.refs.push_back(name(su->obj));
        if (su->cmp != nullptr) {
          item.compare = su->cmp->getText();
          item.compare_where = at(su->cmp);
        }
        if (su->threshold != nullptr) item.numbers.push_back(quantity(su->threshold));
      } else if (dynamic_cast<P::ExpStopAtSuccessContext*>(it) != nullptr) {
        item.kind = K::StopAtSuccess;
      } else if (auto* ev = dynamic_cast<P::ExpEvolveContext*>(it)) {
        item.kind = K::Evolve;
        item.refs.push_back(name(ev->ident()));
        for (P::EsOptionContext* o : ev->esOption()) {
          if (o == nullptr) continue;
          ast::EsOption opt;
          opt.name = name(o->ident());
          opt.where = span(o);
          if (o->lo != nullptr) {
            opt.lo = quantity(o->lo);
            opt.hi = quantity(o->hi);
          } else if (!o->quantity().empty()) {
            opt.value = quantity(o->quantity()[0]);
          }
          item.options.push_back(std::move(opt));
        }
        if (ev->NUMBER() != nullptr) item.generations = number(ev->NUMBER());
      } else if (auto* ru = dynamic_cast<P::ExpRunsContext*>(it)) {
        item.kind = K::Runs;
        item.numbers.push_back(number(ru->NUMBER()));
      } else if (auto* se = dynamic_cast<P::ExpSeedContext*>(it)) {
        item.kind = K::Seed;
        item.numbers.push_back(number(se->NUMBER()));
      } else if (auto* sf = dynamic_cast<P::ExpStartFromContext*>(it)) {
        item.kind = K::StartFrom;
        item.evaluate_only = sf->kw != nullptr && sf->kw->getType() == P::EVALUATE;
        item.refs.push_back(name(sf->ident()));
      } else if (auto* co = dynamic_cast<P::ExpCompareContext*>(it)) {
        item.kind = K::Compare;
        for (P::ComparedContext* cc : co->compared()) {
          if (cc == nullptr) continue;
          item.refs.push_back(name(cc->ctl));
          item.aliases.push_back(cc->alias != nullptr ? name(cc->alias) : ast::Name{});
          item.algorithms.push_back(cc->algo != nullptr ? name(cc->algo) : ast::Name{});
        }
      } else {
        continue;
      }
      x.items.push_back(std::move(item));
    }
    return x;
  }

  // `robot.time_constant`, `mu`, `energy.stop.generations`: one name spanning the key.
  ast::Name setting_key(P::SettingKeyContext* c) const {
    ast::Name n;
    if (c == nullptr) return n;
    n.where = span(c);
    for (antlr4::tree::ParseTree* ch : c->children) {
      if (auto* t = dynamic_cast<antlr4::tree::TerminalNode*>(ch)) {
        if (missing(t)) return ast::Name{{}, n.where};
        n.text += t->getText();
      } else if (auto* k = dynamic_cast<P::KeyPartContext*>(ch)) {
        if (k->ident() == nullptr) {
          antlr4::tree::TerminalNode* word = k->ROBOT() != nullptr ? k->ROBOT() : k->ARENA();
          if (word == nullptr || missing(word)) return ast::Name{{}, n.where};
          n.text += word->getText();
          continue;
        }
        const ast::Name part = name(k->ident());
        if (part.text.empty()) return ast::Name{{}, n.where};
        n.text += part.text;
      }
    }
    return n;
  }

  ast::StudyValue study_value(P::StudyValueContext* c) {
    ast::StudyValue v;
    if (c == nullptr) return v;
    v.where = span(c);
    v.text = source(c);
    if (c->LBRACK() != nullptr) {
      v.list = true;
      for (P::StudyValueContext* item : c->studyValue()) v.items.push_back(study_value(item));
      return v;
    }
    if (c->value() != nullptr) {
      v.value = value(c->value());
    } else {
      v.value.kind = ast::Value::Kind::Word;
      v.value.text = name(c->ident()).text;
      v.value.where = v.where;
    }
    return v;
  }

  ast::StudyDecl study(P::StudyDeclContext* c, int order) {
    ast::StudyDecl s;
    head(s, c, c->name, order);
    using K = ast::StudyItem::Kind;
    const auto settings_of = [&](const std::vector<P::StudySettingContext*>& list, ast::StudyItem& item) {
      for (P::StudySettingContext* st : list)
        if (st != nullptr) item.settings.push_back({setting_key(st->key), study_value(st->studyValue())});
    };
    for (P::StudyItemContext* it : c->studyItem()) {
      if (it == nullptr) continue;
      ast::StudyItem item;
      item.where = at(it->getStart());
      if (auto* cs = dynamic_cast<P::StudyConditionsContext*>(it)) {
        item.kind = K::Conditions;
        for (P::IdentContext* i : cs->ident()) item.experiments.push_back(name(i));
      } else if (auto* cd = dynamic_cast<P::StudyConditionContext*>(it)) {
        item.kind = K::Condition;
        item.name = name(cd->name);
        item.experiments.push_back(name(cd->exp));
        settings_of(cd->studySetting(), item);
      } else if (auto* sw = dynamic_cast<P::StudySweepContext*>(it)) {
        item.kind = K::Sweep;
        item.experiments.push_back(name(sw->exp));
        settings_of(sw->studySetting(), item);
      } else if (auto* ru = dynamic_cast<P::StudyRunsContext*>(it)) {
        item.kind = K::Runs;
        item.number = number(ru->NUMBER());
      } else if (auto* se = dynamic_cast<P::StudySeedContext*>(it)) {
        item.kind = K::Seed;
        item.number = number(se->NUMBER());
      } else {
        continue;
      }
      s.items.push_back(std::move(item));
    }
    return s;
  }

  ast::ExprPtr error_expr(const SourceRange& where) const {
    auto e = std::make_unique<ast::Expr>();
    e->kind = ast::Expr::Kind::Error;
    e->where = where;
    return e;
  }

  ast::ExprPtr binary(std::string op, P::ExprContext* a, P::ExprContext* b, const SourceRange& where,
                      int depth) {
    auto e = std::make_unique<ast::Expr>();
    e->kind = ast::Expr::Kind::Binary;
    e->text = std::move(op);
    e->where = where;
    e->args.push_back(expr(a, depth + 1));
    e->args.push_back(expr(b, depth + 1));
    return e;
  }

  ast::ExprPtr expr(P::ExprContext* c, int depth = 0) {
    using K = ast::Expr::Kind;
    if (c == nullptr) return error_expr(SourceRange{file_, 0, 0, 1});
    const SourceRange where = span(c);
    if (depth > kMaxNesting) {
      if (!deep_reported_) {
        sink_.error(where, "expression nested too deeply (more than " + std::to_string(kMaxNesting) +
                               " levels)")
            .help.push_back("split it, or remove redundant parentheses");
        deep_reported_ = true;
      }
      return error_expr(where);
    }
    auto e = std::make_unique<ast::Expr>();
    e->where = where;
    if (auto* p = dynamic_cast<P::ParenExprContext*>(c)) {
      auto inner = expr(p->expr(), depth + 1);
      inner->where = where;
      return inner;
    }
    if (auto* n = dynamic_cast<P::NumberExprContext*>(c)) {
      ast::Quantity q = number(n->NUMBER());
      add_unit(q, n->unit());
      if (!q.finite) return error_expr(where);
      e->kind = K::Number;
      e->number = q.value;
      e->unit = q.unit;
      e->unit_where = q.unit_where;
      return e;
    }
    if (auto* b = dynamic_cast<P::BoolExprContext*>(c)) {
      e->kind = K::Bool;
      e->number = b->TRUE() != nullptr ? 1.0 : 0.0;
      return e;
    }
    if (auto* f = dynamic_cast<P::CallExprContext*>(c)) {
      const ast::Name n = name(f->ident());
      e->kind = K::Call;
      e->text = n.text;
      e->unit_where = n.where;   // the function name
      for (P::ExprContext* a : f->expr()) e->args.push_back(expr(a, depth + 1));
      return e;
    }
    if (auto* i = dynamic_cast<P::IndexExprContext*>(c)) {
      const ast::Name n = name(i->ident());
      e->kind = K::Index;
      e->text = n.text;
      e->unit_where = n.where;
      e->args.push_back(expr(i->expr(), depth + 1));
      return e;
    }
    if (auto* d = dynamic_cast<P::MemberExprContext*>(c)) {
      const ast::Name library = name(d->ident(0)), member = name(d->member);
      if (library.text.empty() || member.text.empty()) return error_expr(where);
      e->kind = K::Name;
      e->text = library.text + "." + member.text;
      return e;
    }
    if (auto* n = dynamic_cast<P::NameExprContext*>(c)) {
      const ast::Name nm = name(n->ident());
      if (nm.text.empty()) return error_expr(where);
      e->kind = K::Name;
      e->text = nm.text;
      return e;
    }
    if (auto* p = dynamic_cast<P::PowExprContext*>(c)) return binary("^", p->expr(0), p->expr(1), where, depth);
    if (auto* u = dynamic_cast<P::UnaryExprContext*>(c)) {
      if (u->op != nullptr && u->op->getType() == P::PLUS) return expr(u->expr(), depth + 1);
      e->kind = K::Unary;
      e->text = "neg";
      e->args.push_back(expr(u->expr(), depth + 1));
      return e;
    }
    if (auto* m = dynamic_cast<P::MulExprContext*>(c))
      return binary(m->op != nullptr ? m->op->getText() : "*", m->expr(0), m->expr(1), where, depth);
    if (auto* a = dynamic_cast<P::AddExprContext*>(c))
      return binary(a->op != nullptr ? a->op->getText() : "+", a->expr(0), a->expr(1), where, depth);
    if (auto* k = dynamic_cast<P::CmpExprContext*>(c))
      return binary(k->op != nullptr ? k->op->getText() : "==", k->expr(0), k->expr(1), where, depth);
    if (auto* n = dynamic_cast<P::NotExprContext*>(c)) {
      e->kind = K::Unary;
      e->text = "not";
      e->args.push_back(expr(n->expr(), depth + 1));
      return e;
    }
    if (auto* a = dynamic_cast<P::AndExprContext*>(c)) return binary("and", a->expr(0), a->expr(1), where, depth);
    if (auto* o = dynamic_cast<P::OrExprContext*>(c)) return binary("or", o->expr(0), o->expr(1), where, depth);
    if (auto* i = dynamic_cast<P::IfExprContext*>(c)) {
      e->kind = K::If;
      for (int k = 0; k < 3; ++k) e->args.push_back(expr(i->expr(static_cast<std::size_t>(k)), depth + 1));
      return e;
    }
    return error_expr(where);
  }

  std::filesystem::path file_;
  std::string_view text_;
  antlr4::CharStream& chars_;
  Sink& sink_;
  const std::vector<std::size_t>& errors_;
  bool deep_reported_ = false;
};

}  // namespace

ast::Module parse_module(const CleanText& text, const std::filesystem::path& file, Sink& sink) {
  ast::Module m;
  m.file = file;
  const int errors_before = sink.errors();
  for (const CleanText::Bad& b : text.invalid)
    sink.error(SourceRange{file, b.line, b.column, 1}, "invalid UTF-8 in the source text")
        .help.push_back("scripts are UTF-8 text; the byte is shown as \xEF\xBF\xBD");

  try {
    antlr4::ANTLRInputStream input(text.parser);
    grammar::EscLexer lexer(&input);
    SyntaxErrorListener listener(file, text.display, sink);
    lexer.removeErrorListeners();
    lexer.addErrorListener(&listener);
    antlr4::CommonTokenStream tokens(&lexer);
    tokens.fill();
    retype_units(tokens);
    tokens.seek(0);
    listener.set_tokens(&tokens);

    for (antlr4::Token* t : tokens.getTokens())
      if (t->getType() == P::UNTERMINATED_COMMENT) {
        SourceRange opening = token_range(file, t);
        opening.length = 2;
        sink.error(opening, "unterminated comment: `/*` has no closing `*/`")
            .help.push_back("close the comment with `*/`; everything after `/*` was read as a comment");
        m.syntax_ok = false;
        return m;
      }

    if (const antlr4::Token* deep = too_deep(tokens)) {
      sink.error(token_range(file, deep),
                 "too deeply nested: more than " + std::to_string(kMaxNesting) +
                     " levels of brackets and operators")
          .help.push_back("simplify the expression");
      m.syntax_ok = false;
      return m;
    }

    grammar::EscParser parser(&tokens);
    parser.removeErrorListeners();
    parser.addErrorListener(&listener);
    P::ScriptContext* tree = parser.script();
    Builder builder(file, text, input, sink, listener.error_tokens());
    builder.build(tree, m);
  } catch (const std::exception&) {
    sink.error(SourceRange{file, 1, 1, 1}, "internal error: the parser failed on this file");
  } catch (...) {
    sink.error(SourceRange{file, 1, 1, 1}, "internal error: the parser failed on this file");
  }
  m.syntax_ok = sink.errors() == errors_before;
  return m;
}

}  // namespace esc::compiler
