#pragma once

#include <actionlib/action_definition.h>
#include <actionlib/server/action_server.h>
#include <ros/ros.h>

#include <condition_variable>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <variant>

namespace billiard_shot_planner
{
/// An action server that checks a goal before it takes it, as actionlib means its states: a goal the check refuses
/// is REJECTED with the check's result (the server never processed it); an accepted goal runs on the server's own
/// thread, one at a time — a newer goal preempts the running one and recalls a waiting one, as SimpleActionServer
/// does — and `execute` ends it through finish() (or setSucceeded, setAborted, setPreempted). The check's work is
/// not done twice: what it prepared for an accepted goal (a `Job`: the goal read, placed and validated) is what
/// `execute` is handed. The calls inside `execute` act on the running goal, with SimpleActionServer's names.
template <class Action, class Job>
class CheckedActionServer
{
public:
  ACTION_DEFINITION(Action)
  using GoalHandle = actionlib::ServerGoalHandle<Action>;
  /// The job of an accepted goal, or the result to reject it with.
  using Check = std::function<std::variant<Job, Result>(const Goal&)>;
  using Execute = std::function<void(const GoalConstPtr&, Job&)>;

  CheckedActionServer(const ros::NodeHandle& node, const std::string& name, Check check, Execute execute)
      : check_(std::move(check)),
        execute_(std::move(execute)),
        server_(
            node, name, [this](GoalHandle goal) { receive(goal); }, [this](GoalHandle goal) { cancel(goal); }, false)
  {
    worker_ = std::thread([this] { work(); });
    server_.start();
  }

  ~CheckedActionServer()
  {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      shutdown_ = true;
      preempt_ = true;
    }
    ready_.notify_all();
    worker_.join();
  }

  CheckedActionServer(const CheckedActionServer&) = delete;
  CheckedActionServer& operator=(const CheckedActionServer&) = delete;

  bool isPreemptRequested() const
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return preempt_;
  }
  void publishFeedback(const Feedback& feedback) { running().publishFeedback(feedback); }
  void setSucceeded(const Result& result, const std::string& text = "") { running().setSucceeded(result, text); }
  void setAborted(const Result& result, const std::string& text = "") { running().setAborted(result, text); }
  void setPreempted(const Result& result, const std::string& text = "") { running().setCanceled(result, text); }

  /// Ends the running goal as actionlib means it: PREEMPTED with the best so far when a preemption was asked and the
  /// work `ran` to an answer (stopped early, not failed); ABORTED when it failed; SUCCEEDED otherwise.
  void finish(const Result& result, bool ran)
  {
    if (ran && isPreemptRequested())
      setPreempted(result, "preempted: the best found so far");
    else if (!result.success)
      setAborted(result, result.message);
    else
      setSucceeded(result);
  }

private:
  void receive(GoalHandle goal)
  {
    std::variant<Job, Result> verdict = check_(*goal.getGoal());
    if (const Result* refusal = std::get_if<Result>(&verdict))
    {
      goal.setRejected(*refusal, "rejected: the goal cannot be carried out as it is (the result says why)");
      return;
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (waiting_)
        waiting_->first.setCanceled(Result(), "recalled: a newer goal replaced it");
      waiting_.emplace(goal, std::move(std::get<Job>(verdict)));
      preempt_ = running_.has_value();  // a newer goal preempts the running one
    }
    ready_.notify_all();
  }

  void cancel(GoalHandle goal)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (waiting_ && waiting_->first == goal)
    {
      waiting_->first.setCanceled(Result(), "recalled before it ran");
      waiting_.reset();
    }
    else if (running_ && *running_ == goal)
      preempt_ = true;
  }

  void work()
  {
    for (;;)
    {
      std::optional<std::pair<GoalHandle, Job>> next;
      {
        std::unique_lock<std::mutex> lock(mutex_);
        ready_.wait(lock, [this] { return shutdown_ || waiting_.has_value(); });
        if (shutdown_)
        {
          if (waiting_)
            waiting_->first.setCanceled(Result(), "the server shut down");
          return;
        }
        next.swap(waiting_);
        running_ = next->first;
        preempt_ = false;
      }
      next->first.setAccepted("accepted");
      execute_(next->first.getGoal(), next->second);
      std::lock_guard<std::mutex> lock(mutex_);
      running_.reset();
    }
  }

  GoalHandle running()
  {
    std::lock_guard<std::mutex> lock(mutex_);
    return running_.value_or(GoalHandle());
  }

  Check check_;
  Execute execute_;
  mutable std::mutex mutex_;  ///< guards the goals and the flags below against the callbacks and the worker
  std::condition_variable ready_;
  std::optional<std::pair<GoalHandle, Job>> waiting_;  ///< accepted by the check, not yet running
  std::optional<GoalHandle> running_;
  bool preempt_ = false;
  bool shutdown_ = false;
  actionlib::ActionServer<Action> server_;
  std::thread worker_;
};

}  // namespace billiard_shot_planner
