#include "view_player.h"

#include <algorithm>
#include <stdexcept>

namespace glint::cli::view {
namespace {

bool endsWith(const std::string& text, const std::string& suffix) {
    return text.size() >= suffix.size() &&
           text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

const auto kNothing = [](const std::string&) { return false; };

} // namespace

Player::Player(const gpu::Context& context, const FrameSource& source, replay::SessionOptions options)
    : context_(context), source_(source), pending_(std::move(options)) {
    if (source_.count == 0) throw std::invalid_argument("view: the capture has no frames");
    frame_ = source_.frame(0);
    allEffects_ = replay::effectsToRun(frame_, pending_.effects, pending_.settings);
    pending_.effects = allEffects_;
    pending_.intermediates = true; // every pass's outputs can be shown
    pending_.readback = true;
    pending_.readbackFilter = kNothing; // read on demand (image())
    startSession(false);
    runFrame(true);
}

Player::~Player() = default;

void Player::startSession(bool keepNumbering) {
    replay::SessionOptions options = pending_;
    options.firstFrameIndex = keepNumbering ? static_cast<std::uint32_t>(framesRun_) : 0;
    session_.reset(); // its resources go before the next one's are made
    session_ = std::make_unique<replay::Session>(context_, frame_, source_.environment, options);
    sessionStale_ = false;
    namesStale_ = true;
}

const std::vector<std::string>& Player::runningEffects() const {
    return session_->effects();
}

void Player::runFrame(bool cut) {
    if (sessionStale_) {
        startSession(true);
        cut = true; // a new session starts its histories from nothing
    }
    const replay::FrameResult result = session_->run(frame_, cut || framesRun_ == 0);
    ++framesRun_;
    ran_ = pending_;
    timings_ = result.timings;
    counters_ = result.counters;
    images_.clear();
    errors_.clear();
    if (!namesStale_) return;
    // Every image's name, from one full read: they change only with the effects and settings.
    namesStale_ = false;
    const replay::FrameResult all = session_->read(frame_, {});
    viewNames_.clear();
    for (const replay::NamedImage& image : all.images) viewNames_.push_back(image.name);
    for (const replay::ReferenceError& error : replay::referenceErrors(frame_, all, pending_.settings))
        viewNames_.push_back(error.effect + "/error");
}

bool Player::advance(bool loop) {
    bool cut = cut_;
    std::size_t next = index_ + 1;
    if (next >= source_.count) {
        if (!loop) return false;
        next = 0;
        cut = true;
    }
    frame_ = source_.frame(next);
    index_ = next;
    cut_ = false;
    runFrame(cut);
    return true;
}

void Player::revertChanges() {
    pending_ = ran_;
    sessionStale_ = true;
}

std::string Player::setSetting(const std::string& assignment) {
    SettingValues settings = pending_.settings;
    const std::string error = settings.assign(assignment);
    if (!error.empty()) return error;
    // A setting that fixes resources needs a new session (which lists the images again);
    // the others keep the plan's outputs, and so the names.
    if (!session_->changeSettings(settings)) sessionStale_ = true;
    pending_.settings = settings;
    return {};
}

bool Player::effectOn(const std::string& effect) const {
    return std::find(pending_.effects.begin(), pending_.effects.end(), effect) != pending_.effects.end();
}

std::string Player::toggleEffect(const std::string& effect) {
    if (std::find(allEffects_.begin(), allEffects_.end(), effect) == allEffects_.end()) {
        std::string names;
        for (const std::string& name : allEffects_) names += (names.empty() ? "" : ", ") + name;
        return "no effect '" + effect + "' in this replay (" + names + ")";
    }
    std::vector<std::string> effects;
    for (const std::string& name : allEffects_)
        if ((name == effect) != effectOn(name)) effects.push_back(name);
    if (effects.empty()) return "'" + effect + "' is the only effect on; switch another on first";
    pending_.effects = effects;
    sessionStale_ = true;
    return {};
}

std::string Player::defaultView() const {
    for (const std::string& name : viewNames_)
        if (endsWith(name, "/composite")) return name;
    for (const std::string& effect : session_->effects())
        for (const char* output : {"/denoised", "/noisy"})
            if (std::find(viewNames_.begin(), viewNames_.end(), effect + output) != viewNames_.end())
                return effect + output;
    return viewNames_.empty() ? std::string() : viewNames_.front();
}

std::optional<report::Image> Player::image(const std::string& name) {
    if (std::find(viewNames_.begin(), viewNames_.end(), name) == viewNames_.end()) return std::nullopt;
    if (const auto found = images_.find(name); found != images_.end()) return found->second;
    if (endsWith(name, "/error")) {
        const std::string effect = name.substr(0, name.size() - 6);
        const replay::FrameResult inputs = session_->read(frame_, [&](const std::string& image) {
            return image == effect + "/reference" || image == effect + "/denoised" ||
                   image == effect + "/noisy";
        });
        for (replay::ReferenceError& error : replay::referenceErrors(frame_, inputs, pending_.settings))
            if (error.effect == effect) {
                report::Image map = std::move(error.map);
                errors_[effect] = error;
                return images_[name] = std::move(map);
            }
        return std::nullopt;
    }
    replay::FrameResult read =
        session_->read(frame_, [&](const std::string& image) { return image == name; });
    for (replay::NamedImage& image : read.images)
        if (image.name == name) return images_[name] = std::move(image.image);
    return std::nullopt;
}

} // namespace glint::cli::view
